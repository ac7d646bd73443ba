#pragma once
// A scene crosses from Python as JSON text (the package dumps its dict with json.dumps), so
// it is read by the very reader a scene file is: same names, same checks, same messages.

#include <string>

#include "scene/scene.h"
#include "scene/scene_json.h"

namespace lenslab::python {

// The scene `json_text` describes. `path` is the file it was loaded from ("" for none):
// relative paths in it resolve against the file's folder and errors name the file, as
// load_scene_file does. Throws SceneError.
Scene build_scene(const std::string& json_text, const std::string& path,
                  const SceneReadOptions& options = {});

}  // namespace lenslab::python
