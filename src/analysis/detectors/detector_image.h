#pragma once
// The false-colour picture of a detector's irradiance map: the map (inferno colour map,
// u to the right and v up, as seen from the detector's front), a colour bar labelled in
// W/unit², the centroid marked, and the totals written underneath. The command line
// writes it as <name>.png; the editor shows the same picture.

#include "analysis/detectors/detector.h"
#include "image/false_colour.h"
#include "image/image_io.h"

namespace lenslab {

// Linear (false_colour.h): colour in proportion to the irradiance, 0 to the peak.
// `map_size`: pixels along the map's longer side.
Image8 detector_image(const DetectorMeasurement& m, ColourScale scale = ColourScale::Linear,
                      int map_size = 512);

// "W/mm^2" for a detector whose unit is mm.
std::string irradiance_unit(const DetectorMeasurement& m);

}  // namespace lenslab
