#pragma once
// Zernike polynomials on the unit disc, in the two orderings lens-design programs use: for
// wavefronts (analysis/diffraction/zernike.h fits them) and for surfaces (a Zernike sag).
//
// Coordinates: normalised (x, y) = (ρ cos θ, ρ sin θ), θ from the x axis toward y, y
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

#include <vector>

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

// Term j as a polynomial in x and y: c[a * (n + 1) + b] multiplies x^a y^b (n the term's
// radial order, so the vector holds (n + 1)^2 numbers).
std::vector<double> zernike_monomials(ZernikeOrdering ordering, int j);

}  // namespace lenslab
