#pragma once
// A perceptual colour map for false-colour images of measured quantities: inferno
// (black - purple - orange - pale yellow), lightness rising monotonically with the value.

#include "optics/rgb.h"

namespace lenslab {

// sRGB-encoded colour (components in [0, 1]) of t in [0, 1] (clamped; NaN gives 0).
Rgb inferno(double t);

}  // namespace lenslab
