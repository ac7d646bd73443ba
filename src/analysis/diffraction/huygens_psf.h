#pragma once
// The PSF by Huygens' principle: every ray that passed (field_wavefront.h) is a secondary
// source where it meets the reference sphere, with the pupil's amplitude and phase
// A·exp(i2πW); the field at an image point P is the sum of their spherical wavelets,
//   U(P) = Σ A exp(i2πW) exp(i2π n' (|P − S| − R)/λ) · R/|P − S|,
// with the exact distance |P − S| (Born & Wolf, Principles of Optics, 7th ed., section 8.3;
// Zemax's "Huygens PSF"). Unlike the FFT (diffraction.h) it needs no Fraunhofer approximation
// and no pupil grid whose extent fixes the image grid: the image grid is chosen freely, so a
// strongly aberrated or far-spread PSF can be sampled where it lies. Each sample costs one
// wavelet per ray.
//
// Normalised as the FFT PSF: the aberration-free pupil of the same amplitude peaks at 1 at
// the reference point, so an aberrated PSF's largest sample is its Strehl ratio (when the
// grid is fine enough to catch the peak). The grid lies in the image plane, centred on the
// reference point (the chief ray's image point) or `centre` from it, row i along y;
// Psf::coordinate is about the grid's centre.

#include "analysis/diffraction/diffraction.h"
#include "analysis/diffraction/field_wavefront.h"

namespace lenslab {

struct HuygensGrid {
    int size = 64;       // samples a side
    double spacing = 0;  // between samples, in the system's length unit; 0: λN/2, the FFT's
    double centre_x = 0, centre_y = 0;  // the grid's middle sample, against the reference point
};

// Throws std::invalid_argument for a size below 1 or a negative spacing.
Psf huygens_psf(const FieldWavefront& wavefront, const HuygensGrid& grid);

}  // namespace lenslab
