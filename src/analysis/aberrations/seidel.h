#pragma once
// Seidel (third-order) aberration sums, surface by surface, from the paraxial marginal and
// chief rays (Welford, Aberrations of Optical Systems, 1986, ch. 8: the surface
// contributions, the aspheric terms and the primary chromatic terms):
//   A = n i = n (u + y c),  Ā = n (ū + ȳ c),  Δ(x) = x' - x across the surface,
//   S_I   = -A² y Δ(u/n)                 spherical aberration
//   S_II  = -A Ā y Δ(u/n)                coma
//   S_III = -Ā² y Δ(u/n)                 astigmatism
//   S_IV  = -H² c Δ(1/n)                 Petzval curvature
//   S_V   = -Ā³ y Δ(1/n²) + Ā ȳ c (H + Ā y) Δ(1/n)   distortion; the same as
//           (Ā/A)(S_III + S_IV), written without 1/A so a surface with A = 0 is no trouble
//   C_I   = A y Δ(δn/n)                   axial colour
//   C_II  = Ā y Δ(δn/n)                   lateral colour
// with H = n (ū y - u ȳ) the Lagrange invariant (first_order.h) and δn = n(short) - n(long)
// for the two wavelengths of the chromatic block. A conic (or an even asphere's conic and
// A4 term) adds to the sphere's sums the term of its fourth-order sag beyond the sphere's,
//   δS_I = 8 a4 y⁴ (n' - n), a4 = k c³ / 8 + A4,   δS_II = 8 a4 y³ ȳ (n' - n),
//   δS_III = 8 a4 y² ȳ² (n' - n), δS_V = 8 a4 y ȳ³ (n' - n). The S_V form and the aspheric
// term's scale are checked in tests/analysis/test_seidel.cpp (a published table, and a
// hyperboloid whose term must cancel the sphere's S_I).
// The sums are in wavefront units (W040 = S_I / 8 and so on) at the aperture and field of
// the marginal and chief rays; the transverse forms are in the paraxial image plane.

#include <vector>

#include "analysis/system/first_order.h"

namespace lenslab {

struct SeidelSums {
    double spherical = 0;       // S_I
    double coma = 0;            // S_II
    double astigmatism = 0;     // S_III
    double petzval = 0;         // S_IV
    double distortion = 0;      // S_V
    double axial_colour = 0;    // C_I
    double lateral_colour = 0;  // C_II

    SeidelSums& operator+=(const SeidelSums& o);
};

// Transverse aberrations in the paraxial image plane at the edge of the pupil and field,
// from the sums (Welford ch. 8; the same factors as rayoptics'
// seidel_to_transverse_aberration, whose figures the tests reproduce), n' u' the image-space
// marginal ray:
//   spherical S_I / (2 n'u'); sagittal coma S_II / (2 n'u'), tangential coma three times
//   that; tangential field (3 S_III + S_IV) / (2 n'u'), sagittal field (S_III + S_IV) /
//   (2 n'u'), Petzval S_IV / (2 n'u'), distortion S_V / (2 n'u'); axial colour C_I / (n'u'),
//   lateral colour C_II / (n'u').
struct SeidelTransverse {
    double spherical = 0, sagittal_coma = 0, tangential_coma = 0, tangential_field = 0,
           sagittal_field = 0, petzval = 0, distortion = 0, axial_colour = 0, lateral_colour = 0;
    // Longitudinal axial colour -C_I / (n' u'²): the focus at the short wavelength minus
    // that at the long one, paraxially.
    double longitudinal_axial_colour = 0;
};

struct Seidel {
    double short_nm = 0, long_nm = 0;  // the wavelengths of δn
    std::vector<SeidelSums> surfaces;
    SeidelSums total;
    SeidelTransverse transverse;
};

// From the first-order data's marginal and chief rays (at its wavelength).
Seidel seidel_sums(const OpticalSystem& system, const FirstOrder& first_order, double short_nm,
                   double long_nm);

}  // namespace lenslab
