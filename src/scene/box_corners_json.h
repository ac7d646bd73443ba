#pragma once
// A box written as its two corners, [[xmin, ymin, zmin], [xmax, ymax, zmax]] (an implicit
// solid's bounds, a density grid's box).

#include <nlohmann/json_fwd.hpp>
#include <string>

#include "math/aabb.h"

namespace lenslab {

// Throws SceneError at `path` unless `j` is two points, the second above the first in x, y
// and z.
Aabb read_box_corners(const nlohmann::json& j, const std::string& path);

}  // namespace lenslab
