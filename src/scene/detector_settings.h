#pragma once
// What the scene file says about a detector (docs/scene-format.md, "Detectors"): a flat
// object (triangle, disc, rectangle) that measures the light arriving on it. The
// measurement itself is in src/analysis/detector.h.

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

}  // namespace lenslab
