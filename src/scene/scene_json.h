#pragma once
// The scene file format (docs/scene-format.md): JSON in, Scene out, with errors that name
// the JSON path and the reason.

#include <string>

#include <nlohmann/json.hpp>

#include "scene/scene.h"

namespace lenslab {

// Parses scene JSON text. `source` names the text in syntax-error messages (a file name).
// Throws SceneError; the returned scene is built and ready to render.
Scene parse_scene(const std::string& text, const std::string& source = "scene");

// Builds a scene from an already parsed JSON document (an editor's model). Throws SceneError.
Scene scene_from_json(const nlohmann::json& root);

// Reads and parses a scene file. Throws SceneError (unreadable file, syntax, content).
Scene load_scene_file(const std::string& path);

// The built-in default scene (scenes/default.json, compiled in).
const std::string& default_scene_text();
Scene default_scene();

}  // namespace lenslab
