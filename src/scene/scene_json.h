#pragma once
// The scene file format (docs/scene-format.md): JSON in, Scene out, with errors that name
// the JSON path and the reason.

#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "scene/light_json.h"
#include "scene/scene.h"

namespace lenslab {

// What a reader demands beyond the format itself. The renderer needs a camera; the optical
// bench (`lenslab analyze`) reads files that hold only lenses and their materials.
struct SceneReadOptions {
    bool require_camera = true;
    // Scene::build (the BVH, the lights' emission and the photon targets) for the renderer.
    // The optical bench needs only the objects and materials, so it skips that set-up; every
    // check of the file is made either way (Scene::build throws nothing).
    bool build_for_rendering = true;
};

// Parses scene JSON text. `source` names the text in syntax-error messages (a file name).
// Relative paths in the scene (a mesh's OBJ `file`) are looked up in `base_dir` ("" = the
// current directory). Throws SceneError; the returned scene is built and ready to render.
Scene parse_scene(const std::string& text, const std::string& source = "scene",
                  const std::string& base_dir = "", const SceneReadOptions& options = {});

// Builds a scene from an already parsed JSON document (an editor's model), resolving
// relative paths against `base_dir` as parse_scene does. Throws SceneError.
Scene scene_from_json(const nlohmann::json& root, const std::string& base_dir = "",
                      const SceneReadOptions& options = {});

// Reads a scene's `camera` block alone, with the checks and messages scene_from_json gives
// it: an editor moving the camera need not rebuild the objects. Throws SceneError.
CameraSettings camera_from_json(const nlohmann::json& camera);

// Reads and parses a scene file; relative paths in it are relative to the file's folder.
// Throws SceneError (unreadable file, syntax, content).
Scene load_scene_file(const std::string& path, const SceneReadOptions& options = {});

// load_scene_file in two steps, for a caller that changes the JSON in between (the command
// line's overrides): the file's JSON (syntax checked, errors naming the file), then the scene
// it describes (relative paths resolved against the file's folder, errors naming the file).
nlohmann::json read_scene_json_file(const std::string& path);
Scene scene_from_file_json(const nlohmann::json& root, const std::string& path,
                           const SceneReadOptions& options = {});

// The built-in default scene (scenes/default.json, compiled in).
const std::string& default_scene_text();
Scene default_scene();

}  // namespace lenslab
