#pragma once
// Flat open surfaces and detectors in scene files (docs/scene-format.md, "Disc",
// "Rectangle" and "Detectors"):
//
// Their keys, and the detector block's, are declared in planar_spec.cpp.

#include <array>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "geometry/shape.h"
#include "scene/detector_settings.h"
#include "scene/json_reader.h"
#include "scene/spec_reader.h"

namespace lenslab {

// Their declarations (planar_spec.cpp): the common object keys, detector included, and their own.
const ElementSpec& disc_spec();
const ElementSpec& rectangle_spec();

// `r` reads through disc_spec() or rectangle_spec().
std::shared_ptr<const Shape> read_disc(SpecReader& r);
std::shared_ptr<const Shape> read_rectangle(SpecReader& r);

// A flat shape's `up` (given, and not parallel to the unit `normal`, or default_plane_up)
// and a rectangle's `size` [width, height]: the rectangle and disc lights read them too.
Vec3 read_plane_up(JsonObjectReader& r, const Vec3& normal);
std::array<double, 2> read_plane_size(JsonObjectReader& r);

// The `detector` object's keys (planar_spec.cpp).
const ElementSpec& detector_spec();

// The object's `detector` key: nothing when absent or false.
std::optional<DetectorSettings> read_detector(JsonObjectReader& r);

// Refuses a detector so small that its cells' areas underflow, naming the object's key that
// sets its size, `size_key` (`path` is the object's own path).
void check_detector_size(const Shape& shape, const DetectorSettings& d, const std::string& path,
                         const std::string& size_key);

// Refuses `detector` on an object that is not flat (`type` names it in the message).
void check_detector_allowed(const nlohmann::json& object, const std::string& path,
                            const std::string& type);

}  // namespace lenslab
