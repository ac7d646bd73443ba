#include "geometry/triangle.h"

#include <algorithm>
#include <cmath>

namespace lenslab {

Triangle::Triangle(const Vec3& a, const Vec3& b, const Vec3& c)
    : m_v{a, b, c}, m_normal(normalize(cross(b - a, c - a))) {}

// Möller & Trumbore 1997; in double precision the edge cases it misses are far below the
// scene epsilon, and the scene reader rejects degenerate triangles.
bool Triangle::intersect(const Ray& ray, double t_min, double t_max, SurfaceHit& hit) const {
    const Vec3 e1 = m_v[1] - m_v[0];
    const Vec3 e2 = m_v[2] - m_v[0];
    const Vec3 p = cross(ray.direction, e2);
    const double det = dot(e1, p);
    if (std::abs(det) < 1e-300) return false;
    const double inv_det = 1.0 / det;
    const Vec3 s = ray.origin - m_v[0];
    const double u = dot(s, p) * inv_det;
    if (u < 0.0 || u > 1.0) return false;
    const Vec3 q = cross(s, e1);
    const double v = dot(ray.direction, q) * inv_det;
    if (v < 0.0 || u + v > 1.0) return false;
    const double t = dot(e2, q) * inv_det;
    if (!in_range(t, t_min, t_max)) return false;
    hit.t = t;
    hit.point = ray.at(t);
    hit.normal = m_normal;
    return true;
}

Aabb Triangle::bounds() const {
    Aabb b;
    for (const Vec3& v : m_v) b.expand(v);
    return b;
}

std::optional<FlatPatch> Triangle::flat_patch() const {
    // u along the first edge, from the first vertex.
    const Vec3 u = normalize(m_v[1] - m_v[0]);
    FlatPatch p{{m_v[0], u, cross(m_normal, u), m_normal}, 0, 0, 0, 0, 0, {m_v[0], m_v[1], m_v[2]}};
    for (const Vec3& corner : p.corners) {
        p.u0 = std::min(p.u0, p.frame.u_of(corner));
        p.u1 = std::max(p.u1, p.frame.u_of(corner));
        p.v0 = std::min(p.v0, p.frame.v_of(corner));
        p.v1 = std::max(p.v1, p.frame.v_of(corner));
    }
    return p;
}

}  // namespace lenslab
