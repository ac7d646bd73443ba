#include "geometry/lens/spherical_surface.h"

#include <cmath>
#include <sstream>

#include "math/quadratic.h"

namespace lenslab {

double SphericalSurface::sag(double r) const {
    // Written as c r^2 / (1 + sqrt(1 - c^2 r^2)) rather than R - sqrt(R^2 - r^2): no
    // cancellation near the axis, where lens sags are tiny against R.
    const double c = m_curvature;
    return c * r * r / (1.0 + std::sqrt(std::max(0.0, 1.0 - c * c * r * r)));
}

double SphericalSurface::max_semi_diameter() const { return std::abs(m_radius); }

bool SphericalSurface::intersect(const Ray& ray, const SurfaceSpan& span, double t_min,
                                 double t_max, double& t) const {
    // In curvature form, c |p|^2 - 2 p_z = 0 with c = 1/R: no R^2 term to overflow or to
    // swamp the sag of a weakly curved surface, and it tends to the plane z = 0 as c -> 0.
    const double c = m_curvature;
    const Vec3& o = ray.origin;
    const Vec3& d = ray.direction;
    double roots[2];
    if (!solve_half_quadratic(c * dot(d, d), c * dot(o, d) - d.z, c * dot(o, o) - 2.0 * o.z,
                              roots[0], roots[1])) {
        return false;
    }
    const double limit = span.semi_diameter * (1.0 + kSeamTolerance);
    for (double tc : roots) {
        if (!in_range(tc, t_min, t_max)) continue;
        const Vec3 p = ray.at(tc);
        const bool on_vertex_half = p.z * c <= 1.0;
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
    const double c = m_curvature;
    return normalize(Vec3{-c * p.x, -c * p.y, 1.0 - c * p.z});
}

std::string SphericalSurface::describe() const {
    std::ostringstream s;
    s << "sphere R=" << m_radius;
    return s.str();
}

}  // namespace lenslab
