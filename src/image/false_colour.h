#pragma once
// Drawing false-colour pictures of measured maps (a detector's irradiance, a PSF, a
// wavefront): the colour scale, the inferno colours as 8-bit sRGB, filled rectangles.

#include "image/image_io.h"

namespace lenslab {

// Linear: colour in proportion to the value over its range. Log: over the decades below the
// peak (kLogDecades of them), which shows faint halos beside a bright focus.
enum class ColourScale { Linear, Log };
inline constexpr int kLogDecades = 4;

// inferno(t) (colormap.h) as 8-bit sRGB.
void inferno_rgb8(double t, unsigned char (&out)[3]);

// Fills [x0, x1) × [y0, y1), clipped to the image.
void fill_rect(Image8& image, int x0, int y0, int x1, int y1, const unsigned char (&rgb)[3]);

}  // namespace lenslab
