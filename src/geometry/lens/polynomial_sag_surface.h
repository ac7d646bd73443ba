#pragma once
// A freeform face as lens-design programs give it: an even asphere base (a conic of vertex
// radius R, 0 flat, with A4 r^4 + ... + A16 r^16) plus a polynomial in the normalised
// coordinates (x / R_n, y / R_n),
//   z = base(r) + sum over (a, b) of C_ab (x / R_n)^a (y / R_n)^b.
// Two shapes are made of it: an XY polynomial (the C_ab typed) and a Zernike sag (Zemax's
// Zernike Standard Sag: Noll-ordered Zernike terms on the disc of radius R_n, expanded into
// the same polynomial, math/zernike_terms.h). The terms may be non-zero at the vertex (a
// piston, a defocus term's constant): the face then stands off its vertex plane by that much,
// as it does in the lens-design program.

#include <string>
#include <vector>

#include "geometry/lens/analytic_sag_surface.h"

namespace lenslab {

// C_ab for x^a y^b, a, b ≤ degree: c[a * (degree + 1) + b].
struct XyPolynomial {
    int degree = 0;
    std::vector<double> c{0.0};

    static XyPolynomial of_degree(int degree);
    double& at(int a, int b) { return c[a * (degree + 1) + b]; }
    double at(int a, int b) const { return c[a * (degree + 1) + b]; }
    // The value and its gradient at (u, v).
    double evaluate(double u, double v, double& d_du, double& d_dv) const;
};

class PolynomialSagSurface final : public AnalyticSagSurface {
public:
    static constexpr size_t kMaxAsphereCoefficients = 7;  // A4 .. A16

    PolynomialSagSurface(double radius, double k, std::vector<double> asphere_coefficients,
                         double normalization_radius, XyPolynomial terms, std::string kind);

    double sag_and_gradient(double x, double y, double& dz_dx, double& dz_dy) const override;
    double max_semi_diameter() const override;
    std::string describe() const override;
    std::string why_undefined(double x, double y) const override;

private:
    double m_radius, m_c, m_k;
    std::vector<double> m_asphere;
    double m_normalization;
    XyPolynomial m_terms;
    std::string m_kind;  // "XY polynomial" or "Zernike sag", for describe()
};

// XY polynomial coefficients in Zemax's (and CODE V's) order: by degree, then by the power of
// y: x, y, x^2, xy, y^2, x^3, x^2 y, ... (230 terms reach degree 20).
XyPolynomial xy_polynomial_from_terms(const std::vector<double>& terms);

// Noll-ordered Zernike coefficients (Z1, Z2, ...) as one polynomial in (x, y) on the unit disc.
XyPolynomial zernike_sag_polynomial(const std::vector<double>& noll_coefficients);

}  // namespace lenslab
