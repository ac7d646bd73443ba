#pragma once
// Smooth spectra for RGB colours (Jakob and Hanika, "A Low-Dimensional Function Space for
// Efficient Spectral Upsampling", Eurographics 2019): a reflectance
//   s(nm) = sigmoid(c0 x^2 + c1 x + c2),  x = (nm - 595) / 235 (the visible band as [-1, 1]),
//   sigmoid(y) = 1/2 + y / (2 sqrt(1 + y^2)),
// whose colour under D65 is the given linear sRGB. Unlike the three boxes of
// reflectance_from_rgb (optics/spectrum.h) it has no edges: a coloured light through a prism
// fans out into a spectrum without steps. Greys are the constant spectrum, exactly.
//
// The coefficients are solved per colour (damped Gauss-Newton on the same 0.1 nm integral
// spectrum_to_rgb takes, walked out from the grey of the same mean in steps), so a scene's
// few colours cost a few milliseconds to read; no table is stored.

#include <array>
#include <optional>

#include "optics/rgb.h"
#include "optics/spectrum.h"

namespace lenslab {

struct SigmoidPolynomial {
    std::array<double, 3> c{0, 0, 0};  // c0 x^2 + c1 x + c2
    double eval(double nm) const;
};

// The smooth reflectance whose colour under D65 is `rgb` (each channel in [0, 1]), or none
// when the fit does not reach it within `tolerance` of its largest channel (the colour lies
// outside what such spectra can make at that brightness). Greys give c = (0, 0, logit).
std::optional<SigmoidPolynomial> fit_smooth_reflectance(const Rgb& rgb, double tolerance = 1e-6);

// The colour (linear sRGB under D65, the same integral as spectrum_to_rgb) of `s`.
Rgb smooth_reflectance_colour(const SigmoidPolynomial& s);

// An illuminant of colour `rgb` (any brightness, channels >= 0): D65 times a smooth
// reflectance fitted at a fraction of the brightness where saturated colours are in reach,
// scaled back; D65 times boxes (illuminant_from_rgb) when no fit reaches the colour.
// Greys are D65 exactly.
SpectrumPtr smooth_illuminant_from_rgb(const Rgb& rgb);

}  // namespace lenslab
