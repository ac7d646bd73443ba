#include "geometry/lens/asphere_surface.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "geometry/lens/conic_surface.h"
#include "geometry/lens/sag_intersection.h"

namespace lenslab {

AsphereSurface::AsphereSurface(double radius, double k, std::vector<double> coefficients)
    : m_radius(radius), m_k(k), m_coefficients(std::move(coefficients)) {
    if (m_coefficients.size() > kMaxCoefficients) {
        throw std::invalid_argument("AsphereSurface: at most 7 coefficients (A4 .. A16)");
    }
}

double AsphereSurface::sag(double r) const {
    // Horner in r^2: A4 r^4 + A6 r^6 + ... = r^4 (A4 + r^2 (A6 + ...)).
    const double r2 = r * r;
    double poly = 0.0;
    for (size_t i = m_coefficients.size(); i-- > 0;) poly = poly * r2 + m_coefficients[i];
    return ConicSurface::conic_sag(1.0 / m_radius, m_k, r) + poly * r2 * r2;
}

double AsphereSurface::polynomial_slope(double r) const {
    // d/dr of A_{2i} r^{2i} is 2i A_{2i} r^{2i-1}; i = 2 for A4.
    const double r2 = r * r;
    double poly = 0.0;
    for (size_t i = m_coefficients.size(); i-- > 0;) {
        poly = poly * r2 + double(2 * (i + 2)) * m_coefficients[i];
    }
    return poly * r2 * r;
}

double AsphereSurface::slope(double r) const {
    return ConicSurface::conic_slope(1.0 / m_radius, m_k, r) + polynomial_slope(r);
}

double AsphereSurface::max_semi_diameter() const {
    return ConicSurface::conic_max_semi_diameter(1.0 / m_radius, m_k);
}

namespace {

struct AsphereSag {
    const AsphereSurface& s;
    double value(double x, double y) const { return s.sag(std::hypot(x, y)); }
    double value_and_gradient(double x, double y, double& dx, double& dy) const {
        const double r = std::hypot(x, y);
        const double slope_over_r = r > 0.0 ? s.slope(r) / r : 0.0;
        dx = slope_over_r * x;
        dy = slope_over_r * y;
        return s.sag(r);
    }
};

}  // namespace

bool AsphereSurface::intersect(const Ray& ray, const SurfaceSpan& span, double t_min, double t_max,
                               double& t) const {
    AsphereSag sag{*this};
    return intersect_sag(ray, span, t_min, t_max, t, sag);
}

Vec3 AsphereSurface::normal(const Vec3& p) const {
    // The surface z = s(r) has normal (-ds/dx, -ds/dy, 1). Scaled by w = sqrt(1 - (1 + k)
    // c^2 r^2) it stays finite where the conic turns vertical (w = 0, e.g. a hemisphere's
    // rim): w ds/dr = c r + w dP/dr, with P the polynomial.
    const double c = 1.0 / m_radius;
    const double r = std::hypot(p.x, p.y);
    const double w = std::sqrt(std::max(0.0, 1.0 - (1.0 + m_k) * c * c * r * r));
    const double scaled_slope_over_r = c + (r > 0.0 ? w * polynomial_slope(r) / r : 0.0);
    return normalize(Vec3{-scaled_slope_over_r * p.x, -scaled_slope_over_r * p.y, w});
}

std::string AsphereSurface::describe() const {
    std::ostringstream s;
    s << "asphere R=" << m_radius << " k=" << m_k;
    for (size_t i = 0; i < m_coefficients.size(); ++i) {
        s << " A" << 2 * (i + 2) << "=" << m_coefficients[i];
    }
    return s.str();
}

std::string AsphereSurface::why_undefined(double x, double y) const {
    const double c = 1.0 / m_radius;
    if (1.0 - (1.0 + m_k) * c * c * (x * x + y * y) < 0) return "sqrt of a negative number";
    return "";
}

}  // namespace lenslab
