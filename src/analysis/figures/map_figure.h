#pragma once
// A row of false-colour maps on one colour scale, with a colour bar: the PSF images of
// `lenslab analyze --psf-png` and the OPD maps of `--opd-png`, one panel per field.

#include <optional>
#include <string>
#include <vector>

#include "image/false_colour.h"

namespace lenslab {

struct MapPanel {
    std::string label;  // under the panel
    int width = 0, height = 0;
    std::vector<double> values;  // row-major, row 0 at the top; NaN: no value (drawn grey)
};

struct MapFigure {
    std::string title;
    std::string unit;  // of the values, over the colour bar
    std::vector<MapPanel> panels;
    ColourScale scale = ColourScale::Linear;  // Linear: the range; Log: decades below its top
    // The colour bar's range; none: the values' lowest and highest.
    std::optional<double> low, high;
    std::vector<std::string> footer;
};

// Each panel drawn `panel_pixels` wide (nearest sample). Throws std::invalid_argument for a
// panel whose values do not fill its width × height.
Image8 map_figure_image(const MapFigure& figure, int panel_pixels = 220);

}  // namespace lenslab
