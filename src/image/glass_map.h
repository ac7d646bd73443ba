#pragma once
// The glass map every catalogue prints: n_d up, V_d decreasing to the right, one mark per
// glass coloured by its maker, the best-known glasses labelled. As SVG, or as an image for a
// PNG drawn with the project's own font.

#include <string>
#include <vector>

#include "image/image_io.h"
#include "optics/glass.h"

namespace lenslab {

// The plot's frame: pixel size, the plotting area inside the margins, and the value ranges
// its edges stand for (V_d from v_max at the left to v_min at the right).
struct GlassMapFrame {
    int width = 960, height = 640;
    double left = 70, right = 930, top = 40, bottom = 590;  // plotting area, pixels
    double v_min = 0, v_max = 100, n_min = 1.4, n_max = 2.0;

    double x(double v_d) const { return left + (v_max - v_d) / (v_max - v_min) * (right - left); }
    double y(double n_d) const { return top + (n_max - n_d) / (n_max - n_min) * (bottom - top); }
};

// The glasses that have both an n_d and a V_d (glass_search.h), the ones the map shows.
std::vector<const Glass*> glasses_on_map(const std::vector<const Glass*>& glasses);

// A frame whose ranges hold every glass of the map, rounded out to its grid lines.
GlassMapFrame glass_map_frame(const std::vector<const Glass*>& on_map);

// The map as an SVG document: one <circle class="glass"> per glass of glasses_on_map, with
// data-name and data-maker attributes, at (frame.x(V_d), frame.y(n_d)).
std::string glass_map_svg(const std::vector<const Glass*>& glasses);

// The same map drawn into an image, for a PNG.
Image8 glass_map_image(const std::vector<const Glass*>& glasses);

}  // namespace lenslab
