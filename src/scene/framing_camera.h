#pragma once
// A camera made for a scene file that has none (a lens file for the optical bench, which
// needs no camera): the editor opens such a file with it instead of refusing it.

#include <nlohmann/json.hpp>

#include "scene/scene.h"

namespace lenslab {

// A `camera` block that shows all of `scene` (its bounds), from a three-quarter view above
// and to the side of its centre, as {"position", "look_at", "fov"}. A scene with nothing in
// it gets the default camera's view of the origin.
nlohmann::json framing_camera_json(const Scene& scene);

}  // namespace lenslab
