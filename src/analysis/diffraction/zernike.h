#pragma once
// The least-squares fit of a sampled wavefront (pupil_function.h) to Zernike polynomials
// (math/zernike_terms.h: the orderings, normalisations and coordinates).
//
// A wavefront W020 ρ² has Noll Z4 = W020 / (2√3) and Fringe Z4 = W020 / 2, and W040 ρ⁴ has
// Noll Z11 = W040 / (6√5) (Mahajan, Optical Imaging and Aberrations, part II, table 4-1).

#include <string>
#include <vector>

#include "analysis/diffraction/pupil_function.h"
#include "math/zernike_terms.h"

namespace lenslab {

struct ZernikeFit {
    ZernikeOrdering ordering = ZernikeOrdering::Noll;
    std::vector<double> coefficients;  // waves; coefficients[j - 1] for term j
    double residual_rms = 0;           // waves: what the terms leave of the wavefront
};

// Least-squares fit of the pupil's wavefront (opd_waves where amplitude > 0, each sample
// weighted alike, the pupil's rim at ρ = 1) to terms 1..terms. Throws std::invalid_argument
// when fewer samples than terms pass, or the samples cannot tell the terms apart.
ZernikeFit fit_zernike(const PupilFunction& pupil, ZernikeOrdering ordering, int terms);

}  // namespace lenslab
