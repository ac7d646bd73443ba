#include "geometry/disc.h"

#include <algorithm>

namespace lenslab {

Disc::Disc(const Vec3& centre, const Vec3& normal, double radius, const Vec3& up)
    : m_frame(PlaneFrame::from_normal_up(centre, normal, up)), m_radius(radius) {}

bool Disc::intersect(const Ray& ray, double t_min, double t_max, SurfaceHit& hit) const {
    const auto t = m_frame.ray_t(ray, t_min, t_max);
    if (!t) return false;
    const Vec3 p = ray.at(*t);
    const double u = m_frame.u_of(p), v = m_frame.v_of(p);
    if (u * u + v * v > m_radius * m_radius) return false;
    hit.t = *t;
    hit.point = p;
    hit.normal = m_frame.n;
    return true;
}

Aabb Disc::bounds() const {
    // Along axis a the disc reaches r sqrt(1 - n_a^2) either side of its centre.
    Aabb b;
    Vec3 half;
    for (int a = 0; a < 3; ++a)
        half[a] = m_radius * std::sqrt(std::max(0.0, 1.0 - m_frame.n[a] * m_frame.n[a]));
    b.expand(m_frame.origin - half);
    b.expand(m_frame.origin + half);
    return b;
}

std::optional<FlatPatch> Disc::flat_patch() const {
    return FlatPatch{m_frame, -m_radius, m_radius, -m_radius, m_radius, m_radius, {}};
}

}  // namespace lenslab
