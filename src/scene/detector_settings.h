#pragma once
// What the scene file says about a detector (docs/scene-format.md, "Detectors"): a flat
// object (triangle, disc, rectangle) that measures the light arriving on it. The
// measurement itself is in src/analysis/detectors/detector.h.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace lenslab {

enum class DetectorSide { Front, Back, Both };

struct DetectorSettings {
    // Cells along the surface's u and v; 0 means "square cells, `resolution_long` along
    // the longer side".
    int cells_u = 0, cells_v = 0;
    int resolution_long = 64;
    // Wavelength band edges in nm, increasing: band i is [edges[i], edges[i + 1]). The
    // default splits the visible range where the renderer's colour bands meet.
    std::vector<double> band_edges{360, 490, 585, 830};
    DetectorSide side = DetectorSide::Front;
    // The scene's length unit, only to label results ("mm": irradiance in W/mm^2).
    std::string unit = "unit";
};

// Cells along u and v for a detector `width` by `height` (its extent in its own frame):
// as given, or square-ish with `resolution_long` along the longer side.
inline void detector_cells(const DetectorSettings& d, double width, double height, int& nu,
                           int& nv) {
    if (d.cells_u > 0) {
        nu = d.cells_u;
        nv = d.cells_v;
        return;
    }
    const double longer = std::max(width, height);
    nu = std::max(1, static_cast<int>(std::lround(d.resolution_long * width / longer)));
    nv = std::max(1, static_cast<int>(std::lround(d.resolution_long * height / longer)));
}

// A detector's cells must be at least this wide, so that a cell's area, its reciprocal and
// a disc's squared radius are ordinary (normal) doubles: a 1e-160 disc would otherwise
// report infinite irradiance. (Scene numbers are at most 1e15, so nothing overflows.)
inline constexpr double kMinDetectorCell = 1e-100;

}  // namespace lenslab
