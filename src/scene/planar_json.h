#pragma once
// Flat open surfaces and detectors in scene files (docs/scene-format.md, "Disc",
// "Rectangle" and "Detectors"):
//
// disc      | center    | point, required        | centre
//           | normal    | direction, required    | the front side
//           | radius    | number > 0, required   | radius
//           | up        | direction, optional    | orients (u, v): default [0, 1, 0] ([0, 0, -1] when the normal is vertical)
// rectangle | center, normal, up as for a disc
//           | size      | [width, height] > 0    | width along u = up x normal, height along v
// any of triangle, disc, rectangle:
//           | detector  | true, false or object  | {"resolution", "bands", "side", "unit"}

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geometry/shape.h"
#include "scene/detector_settings.h"
#include "scene/json_reader.h"

namespace lenslab {

// Keys of each type besides type, name, material and detector.
const std::vector<std::string>& disc_keys();
const std::vector<std::string>& rectangle_keys();

std::shared_ptr<const Shape> read_disc(JsonObjectReader& r);
std::shared_ptr<const Shape> read_rectangle(JsonObjectReader& r);

// The object's `detector` key: nothing when absent or false.
std::optional<DetectorSettings> read_detector(JsonObjectReader& r);

// Refuses `detector` on an object that is not flat (`type` names it in the message).
void check_detector_allowed(const nlohmann::json& object, const std::string& path, const std::string& type);

}  // namespace lenslab
