#pragma once
// Writes a ray diagram (ray_diagram.h) as a standalone SVG picture.

#include <string>

#include "analysis/figures/ray_diagram.h"

namespace lenslab {

// The picture is `width` pixels wide; its height follows from the diagram's aspect (lens
// shapes keep their true proportions), at least `min_height`.
std::string ray_diagram_svg(const RayDiagram& diagram, double width = 1200,
                            double min_height = 360);

}  // namespace lenslab
