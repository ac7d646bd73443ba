#include "geometry/lens/polynomial_sag_surface.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "geometry/lens/conic_surface.h"
#include "math/zernike_terms.h"

namespace lenslab {

XyPolynomial XyPolynomial::of_degree(int degree) {
    XyPolynomial p;
    p.degree = degree;
    p.c.assign((degree + 1) * (degree + 1), 0.0);
    return p;
}

double XyPolynomial::evaluate(double u, double v, double& d_du, double& d_dv) const {
    // Horner in v inside Horner in u: row a is sum_b C_ab v^b.
    double value = 0.0, du = 0.0, dv = 0.0;
    for (int a = degree; a >= 0; --a) {
        double row = 0.0, row_dv = 0.0;
        for (int b = degree; b >= 0; --b) {
            row_dv = row_dv * v + row;
            row = row * v + at(a, b);
        }
        du = du * u + value;
        value = value * u + row;
        dv = dv * u + row_dv;
    }
    d_du = du;
    d_dv = dv;
    return value;
}

PolynomialSagSurface::PolynomialSagSurface(double radius, double k,
                                           std::vector<double> asphere_coefficients,
                                           double normalization_radius, XyPolynomial terms,
                                           std::string kind)
    : m_radius(radius),
      m_c(radius == 0 ? 0.0 : 1.0 / radius),
      m_k(k),
      m_asphere(std::move(asphere_coefficients)),
      m_normalization(normalization_radius),
      m_terms(std::move(terms)),
      m_kind(std::move(kind)) {
    if (m_asphere.size() > kMaxAsphereCoefficients) {
        throw std::invalid_argument("PolynomialSagSurface: at most 7 coefficients (A4 .. A16)");
    }
    if (!(m_normalization > 0)) {
        throw std::invalid_argument("PolynomialSagSurface: the normalisation radius must be > 0");
    }
}

double PolynomialSagSurface::sag_and_gradient(double x, double y, double& dz_dx,
                                              double& dz_dy) const {
    const double r2 = x * x + y * y, r = std::sqrt(r2);
    if (1.0 - (1.0 + m_k) * m_c * m_c * r2 < 0) {
        dz_dx = dz_dy = std::numeric_limits<double>::quiet_NaN();
        return dz_dx;
    }
    // The base: conic plus even terms, and dz/dr divided by r (finite on the axis).
    double poly = 0.0, dpoly = 0.0;
    for (size_t i = m_asphere.size(); i-- > 0;) {
        poly = poly * r2 + m_asphere[i];
        dpoly = dpoly * r2 + double(2 * (i + 2)) * m_asphere[i];
    }
    const double root = std::sqrt(1.0 - (1.0 + m_k) * m_c * m_c * r2);
    const double conic_over_r = m_c / root;  // d/dr of the conic sag, over r
    const double slope_over_r = conic_over_r + dpoly * r2;
    double du, dv;
    const double terms = m_terms.evaluate(x / m_normalization, y / m_normalization, du, dv);
    dz_dx = slope_over_r * x + du / m_normalization;
    dz_dy = slope_over_r * y + dv / m_normalization;
    return ConicSurface::conic_sag(m_c, m_k, r) + poly * r2 * r2 + terms;
}

double PolynomialSagSurface::max_semi_diameter() const {
    return ConicSurface::conic_max_semi_diameter(m_c, m_k);
}

std::string PolynomialSagSurface::describe() const {
    std::ostringstream s;
    s << m_kind << " R=" << m_radius << " k=" << m_k << " normalization R=" << m_normalization;
    return s.str();
}

std::string PolynomialSagSurface::why_undefined(double x, double y) const {
    double dx, dy;
    return std::isnan(sag_and_gradient(x, y, dx, dy)) ? "sqrt of a negative number" : "";
}

XyPolynomial xy_polynomial_from_terms(const std::vector<double>& terms) {
    // The degree of the last term: terms of degrees 1..d number d (d + 3) / 2.
    int degree = 1;
    while (degree * (degree + 3) / 2 < int(terms.size())) ++degree;
    XyPolynomial p = XyPolynomial::of_degree(degree);
    size_t i = 0;
    for (int d = 1; d <= degree; ++d) {
        for (int k = 0; k <= d && i < terms.size(); ++k, ++i) p.at(d - k, k) = terms[i];
    }
    return p;
}

XyPolynomial zernike_sag_polynomial(const std::vector<double>& noll_coefficients) {
    int degree = 0;
    for (size_t j = 1; j <= noll_coefficients.size(); ++j) {
        if (noll_coefficients[j - 1] != 0.0) {
            degree = std::max(degree, zernike_index(ZernikeOrdering::Noll, int(j)).n);
        }
    }
    XyPolynomial p = XyPolynomial::of_degree(degree);
    for (size_t j = 1; j <= noll_coefficients.size(); ++j) {
        const double coefficient = noll_coefficients[j - 1];
        if (coefficient == 0.0) continue;
        const int n = zernike_index(ZernikeOrdering::Noll, int(j)).n;
        const std::vector<double> term = zernike_monomials(ZernikeOrdering::Noll, int(j));
        for (int a = 0; a <= n; ++a) {
            for (int b = 0; b <= n; ++b) p.at(a, b) += coefficient * term[a * (n + 1) + b];
        }
    }
    return p;
}

}  // namespace lenslab
