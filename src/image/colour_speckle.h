#pragma once
// How much a picture's colour changes from pixel to pixel inside a disc: the colour-speckle
// index issue 39 measures glass and caustics by. For each pixel, its chroma (R - G, G - B),
// with 8-bit sRGB values read as 0 to 1, against the mean chroma of its 5 x 5 neighbourhood
// (the picture's edge pixels repeated outwards); the index is the mean over the disc's pixels
// of |dR-G| + |dG-B|. A smooth picture scores near 0, one random colour per pixel (one
// wavelength per camera sample behind dispersive glass) near 1. Grey noise scores 0: only
// colour counts.

#include "image/image_io.h"

namespace lenslab {

// A disc of pixels: centre (x right, y down, pixel centres at whole numbers) and radius.
struct PixelDisc {
    double cx = 0, cy = 0, radius = 0;
};

// The index over the pixels (x, y) with (x - cx)^2 + (y - cy)^2 <= radius^2; 0 when the disc
// holds none.
double colour_speckle(const Image8& image, const PixelDisc& disc);

}  // namespace lenslab
