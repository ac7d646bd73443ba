#pragma once
// The Fraunhofer PSF of a sampled pupil on any image grid, by the matrix Fourier transform
// (Soummer et al., Optics Express 15, 15935 (2007)): U = Eᵧ · P · Eₓᵀ with
//   Eₓ[m][j] = exp(−i2π X_m x_j / (2λN)), Eᵧ likewise,
// X_m the image coordinates and x_j the normalised pupil coordinates (the pupil's rim at 1).
// The same transform as the FFT PSF (diffraction.h: a tilt W = t·x moves the image to
// x = 2tλN; normalised so the aberration-free pupil peaks at 1 at the reference point), but the
// grid's spacing, size and centre are free: the wavelengths of a polychromatic PSF can share
// one grid, and the grid can sit on a PSF far from the reference point. Cost: two products of
// (size × pupil samples) matrices, no padding.

#include "analysis/diffraction/diffraction.h"
#include "analysis/diffraction/pupil_function.h"

namespace lenslab {

struct ImageGrid {
    int size = 64;                      // samples a side
    double spacing = 0;                 // between samples (system length unit); must be > 0
    double centre_x = 0, centre_y = 0;  // the grid's middle sample, against the reference point
};

// Psf::coordinate(j) is then relative to the grid's centre. Throws std::invalid_argument for
// a size below 1 or a spacing that is not positive, or a pupil that passes no light.
Psf matrix_psf(const PupilFunction& pupil, const ImageGrid& grid);

}  // namespace lenslab
