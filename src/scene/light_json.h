#pragma once
// The scene's "lights" array read into its lights (point, beam, laser, spot), through their
// declarations (light_spec.h).

#include <nlohmann/json_fwd.hpp>

#include "scene/light.h"

namespace lenslab {

// A scene's `lights` array alone, checked as scene_from_json checks it: an editor changing a
// light need not rebuild the objects. Throws SceneError.
SceneLights lights_from_json(const nlohmann::json& lights);

}  // namespace lenslab
