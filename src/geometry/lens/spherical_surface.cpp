#include "geometry/lens/spherical_surface.h"

#include <cmath>
#include <sstream>

#include "math/quadratic.h"

namespace lenslab {

double SphericalSurface::sag(double r) const {
    // Written as c r^2 / (1 + sqrt(1 - c^2 r^2)) rather than R - sqrt(R^2 - r^2): no
    // cancellation near the axis, where lens sags are tiny against R.
    const double c = 1.0 / m_radius;
    return c * r * r / (1.0 + std::sqrt(std::max(0.0, 1.0 - c * c * r * r)));
}

double SphericalSurface::max_semi_diameter() const { return std::abs(m_radius); }

bool SphericalSurface::intersect(const Ray& ray, double semi_diameter, double t_min,
                                 double t_max, double& t) const {
    const Vec3 oc{ray.origin.x, ray.origin.y, ray.origin.z - m_radius};
    double roots[2];
    if (!solve_half_quadratic(dot(ray.direction, ray.direction), dot(oc, ray.direction),
                              dot(oc, oc) - m_radius * m_radius, roots[0], roots[1])) {
        return false;
    }
    const double limit = semi_diameter * (1.0 + kSeamTolerance);
    for (double tc : roots) {
        if (tc <= t_min || tc >= t_max) continue;
        const Vec3 p = ray.at(tc);
        const bool on_vertex_half = p.z / m_radius <= 1.0;
        if (on_vertex_half && p.x * p.x + p.y * p.y <= limit * limit) {
            t = tc;
            return true;
        }
    }
    return false;
}

Vec3 SphericalSurface::normal(const Vec3& p) const {
    // (centre - p) / R: the centre lies on the +z side for R > 0 and the -z side for R < 0,
    // so dividing by the signed radius always gives a positive z component on the cap.
    return normalize(Vec3{-p.x, -p.y, m_radius - p.z} / m_radius);
}

std::string SphericalSurface::describe() const {
    std::ostringstream s;
    s << "sphere R=" << m_radius;
    return s.str();
}

}  // namespace lenslab
