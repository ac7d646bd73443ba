#include "geometry/lens/conic_surface.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "math/quadratic.h"

namespace lenslab {

double ConicSurface::conic_sag(double c, double k, double r) {
    // The form with the square root in the denominator has no cancellation near the axis and
    // stays finite for a paraboloid (k = -1). Rounding just past the largest semi-diameter
    // is clamped, as for the sphere; the lens refuses diameters beyond it.
    const double s = 1.0 - (1.0 + k) * c * c * r * r;
    return c * r * r / (1.0 + std::sqrt(std::max(0.0, s)));
}

double ConicSurface::conic_slope(double c, double k, double r) {
    // d/dr of the sag: c r / sqrt(1 - (1 + k) c^2 r^2).
    const double s = 1.0 - (1.0 + k) * c * c * r * r;
    return c * r / std::sqrt(std::max(0.0, s));
}

double ConicSurface::conic_max_semi_diameter(double c, double k) {
    if (1.0 + k <= 0.0) return std::numeric_limits<double>::infinity();
    return 1.0 / (std::abs(c) * std::sqrt(1.0 + k));
}

double ConicSurface::sag(double r) const { return conic_sag(m_curvature, m_k, r); }

double ConicSurface::max_semi_diameter() const { return conic_max_semi_diameter(m_curvature, m_k); }

bool ConicSurface::intersect(const Ray& ray, const SurfaceSpan& span, double t_min, double t_max,
                             double& t) const {
    // c (x^2 + y^2 + q z^2) - 2 z = 0 with q = 1 + k, along o + t d: a quadratic in
    // curvature form, like the sphere's (q = 1), with no R^2 term to lose precision to.
    const double c = m_curvature;
    const double q = 1.0 + m_k;
    const Vec3& o = ray.origin;
    const Vec3& d = ray.direction;
    double roots[2];
    if (!solve_half_quadratic(c * (d.x * d.x + d.y * d.y + q * d.z * d.z),
                              c * (o.x * d.x + o.y * d.y + q * o.z * d.z) - d.z,
                              c * (o.x * o.x + o.y * o.y + q * o.z * o.z) - 2.0 * o.z, roots[0],
                              roots[1])) {
        return false;
    }
    const double limit = span.semi_diameter * (1.0 + kSeamTolerance);
    for (double tc : roots) {
        if (!in_range(tc, t_min, t_max)) continue;
        const Vec3 p = ray.at(tc);
        // The vertex sheet: 1 - q c z = sqrt(1 - q c^2 r^2) >= 0 there.
        const bool on_vertex_sheet = q * c * p.z <= 1.0;
        if (on_vertex_sheet && p.x * p.x + p.y * p.y <= limit * limit) {
            t = tc;
            return true;
        }
    }
    return false;
}

Vec3 ConicSurface::normal(const Vec3& p) const {
    // Minus the gradient of c (x^2 + y^2 + q z^2) - 2 z, halved: (-c x, -c y, 1 - q c z),
    // whose z component is sqrt(1 - q c^2 r^2) >= 0 on the vertex sheet.
    const double c = m_curvature;
    return normalize(Vec3{-c * p.x, -c * p.y, 1.0 - (1.0 + m_k) * c * p.z});
}

std::string ConicSurface::describe() const {
    std::ostringstream s;
    s << "conic R=" << m_radius << " k=" << m_k;
    return s.str();
}

std::string ConicSurface::why_undefined(double x, double y) const {
    const double c = m_curvature;
    if (1.0 - (1.0 + m_k) * c * c * (x * x + y * y) < 0) return "sqrt of a negative number";
    return "";
}

}  // namespace lenslab
