#include "geometry/sphere.h"

#include "math/quadratic.h"

namespace lenslab {

bool Sphere::intersect(const Ray& ray, double t_min, double t_max, SurfaceHit& hit) const {
    const Vec3 oc = ray.origin - m_centre;
    double t0, t1;
    if (!solve_half_quadratic(dot(ray.direction, ray.direction), dot(oc, ray.direction),
                              dot(oc, oc) - m_radius * m_radius, t0, t1)) {
        return false;
    }
    double t = t0;
    if (!in_range(t, t_min, t_max)) {
        t = t1;
        if (!in_range(t, t_min, t_max)) return false;
    }
    hit.t = t;
    hit.point = ray.at(t);
    hit.normal = (hit.point - m_centre) / m_radius;
    return true;
}

Aabb Sphere::bounds() const {
    const Vec3 r{m_radius, m_radius, m_radius};
    return {m_centre - r, m_centre + r};
}

}  // namespace lenslab
