#include "geometry/rectangle.h"

#include <cmath>

namespace lenslab {

Rectangle::Rectangle(const Vec3& centre, const Vec3& normal, double width, double height,
                     const Vec3& up)
    : m_frame(PlaneFrame::from_normal_up(centre, normal, up)), m_width(width), m_height(height) {}

bool Rectangle::intersect(const Ray& ray, double t_min, double t_max, SurfaceHit& hit) const {
    const auto t = m_frame.ray_t(ray, t_min, t_max);
    if (!t) return false;
    const Vec3 p = ray.at(*t);
    if (std::abs(m_frame.u_of(p)) > 0.5 * m_width || std::abs(m_frame.v_of(p)) > 0.5 * m_height)
        return false;
    hit.t = *t;
    hit.point = p;
    hit.normal = m_frame.n;
    return true;
}

Aabb Rectangle::bounds() const {
    Aabb b;
    for (double su : {-0.5, 0.5}) {
        for (double sv : {-0.5, 0.5}) b.expand(m_frame.at(su * m_width, sv * m_height));
    }
    return b;
}

std::optional<FlatPatch> Rectangle::flat_patch() const {
    const double w = 0.5 * m_width, h = 0.5 * m_height;
    return FlatPatch{m_frame,
                     -w,
                     w,
                     -h,
                     h,
                     0,
                     {m_frame.at(-w, -h), m_frame.at(w, -h), m_frame.at(w, h), m_frame.at(-w, h)}};
}

}  // namespace lenslab
