#pragma once
// Reading a scene file's `render` block on its own (scene_json.cpp reads it with the rest).

#include <nlohmann/json.hpp>

#include "scene/render_settings.h"

namespace lenslab {

// Throws SceneError naming "render.KEY". The command line checks a file's own block this way
// before overriding it, as it did when it overrode a scene already read.
RenderSettings read_render_settings(const nlohmann::json& render);

}  // namespace lenslab
