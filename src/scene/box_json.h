#pragma once
// A rectangular block (docs/scene-format.md, "Box"): a closed mesh of 12 triangles, so a
// glass box refracts as a solid (a slab, a light guide, a cuvette's wall).
//
// box | center | point, required           | centre
//     | size   | [x, y, z], each > 0        | full edge lengths along the box's own axes
//     | up     | direction, [0, 1, 0]       | where the box's y edges point
//     | facing | direction, [0, 0, 1]       | where its z edges point (perpendicular to up)
//
// The box's x edges run along cross(up, facing), as a mesh's model axes do.

#include <memory>

#include "geometry/shape.h"
#include "scene/param_spec.h"
#include "scene/spec_reader.h"

namespace lenslab {

// Its declaration: the common object keys (no detector) and its own.
const ElementSpec& box_spec();

// `r` reads through box_spec(); errors name the JSON path.
std::shared_ptr<const Shape> read_box(SpecReader& r);

}  // namespace lenslab
