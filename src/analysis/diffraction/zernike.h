#pragma once
// Zernike polynomials on the unit pupil and the least-squares fit of a sampled wavefront
// (pupil_function.h) to them, in the two orderings lens-design programs report.
//
// Coordinates: normalised pupil (x, y) = (ρ cos θ, ρ sin θ), θ from the x axis toward y, y
// the meridional direction (the field lies along y). Each term is R_n^|m|(ρ) times cos(mθ)
// for m > 0, sin(|m|θ) for m < 0, and 1 for m = 0.
//
// - Noll (Zemax's "Standard"; Noll, J. Opt. Soc. Am. 66, 207 (1976)): j = 1, 2, ... ordered
//   by n, then |m|; even j carries cos, odd j sin. Orthonormal: each term's mean square over
//   the unit disc is 1 (factor √(2(n+1)) for m ≠ 0, √(n+1) for m = 0), so the RMS of the
//   wavefront is the root sum of squares of the coefficients past piston.
//   Z4 = √3 (2ρ² − 1) (defocus), Z11 = √5 (6ρ⁴ − 6ρ² + 1) (primary spherical),
//   Z7 = √8 (3ρ³ − 2ρ) sin θ (coma along y).
// - Fringe (University of Arizona; Zemax's "Fringe", 37 terms): ordered by (n + |m|)/2, then
//   by |m| decreasing, cos before sin; not normalised (each term is 1 at ρ = 1, θ = 0 for
//   m ≥ 0). Z4 = 2ρ² − 1, Z9 = 6ρ⁴ − 6ρ² + 1, Z8 = (3ρ³ − 2ρ) sin θ.
//
// So a wavefront W020 ρ² has Noll Z4 = W020 / (2√3) and Fringe Z4 = W020 / 2, and W040 ρ⁴ has
// Noll Z11 = W040 / (6√5) (Mahajan, Optical Imaging and Aberrations, part II, table 4-1).

#include <string>
#include <vector>

#include "analysis/diffraction/pupil_function.h"

namespace lenslab {

enum class ZernikeOrdering { Noll, Fringe };
const char* zernike_ordering_name(ZernikeOrdering ordering);  // "noll", "fringe"

struct ZernikeIndex {
    int n = 0;  // radial order
    int m = 0;  // azimuthal frequency; < 0: sin(|m| θ)
};

// The (n, m) of term j (1-based). Throws std::invalid_argument for j < 1, or j > 37 for Fringe
// (the set the Fringe ordering is defined for).
ZernikeIndex zernike_index(ZernikeOrdering ordering, int j);

// Term j at (ρ, θ), with the ordering's normalisation.
double zernike_value(ZernikeOrdering ordering, int j, double rho, double theta);

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
