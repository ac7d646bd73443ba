#pragma once
// A ray diagram (ray_diagram.h), or any figure of the bench in its model, drawn into an 8-bit
// image for a PNG: the same layout as the SVG (diagram_canvas.h), lines and dots rasterised
// here, text in the project's bitmap font.

#include "analysis/figures/ray_diagram.h"
#include "image/image_io.h"

namespace lenslab {

Image8 ray_diagram_image(const RayDiagram& diagram, double width = 1200, double min_height = 360);

}  // namespace lenslab
