#pragma once
// How radiance brighter than white is shown: in a PNG (image_io.h), the editor's view and
// Python's write_image (the scene's render block chooses it: scene/render_tone_map.h):
//   clip: each channel, scaled by 2^exposure, is clipped at 1 (POV-Ray's and pbrt's PNGs);
//   log:  a pixel whose brightest channel is at most kToneMapKnee is shown as with clip;
//         a brighter one on a logarithmic scale that reaches the top `highlight_stops` stops
//         above the knee, its channels scaled together so its colour stays (hue and
//         saturation: no channel passes 1). A caustic many times brighter than
//         the floor keeps its structure (the rim and centre of spherical aberration, a
//         dispersion fringe's colour) instead of one white blot, and the rest of the picture
//         is unchanged.
// EXR files stay linear: exposure applies, the tone map does not.

#include "image/film.h"

namespace lenslab {

// Brightest channel from which `log` compresses (linear, after the exposure).
inline constexpr double kToneMapKnee = 0.5;

struct ToneMap {
    double exposure_stops = 0;
    bool log_highlights = false;  // tone_map "log"
    double highlight_stops = 8;

    // Linear radiance -> display-linear, every channel in [0, 1].
    PixelRgb apply(const PixelRgb& linear) const;
};

}  // namespace lenslab
