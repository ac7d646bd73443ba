#pragma once

#include "geometry/shape.h"

namespace lenslab {

// A single flat triangle, two-sided; its normal follows the vertex order (right-hand rule).
class Triangle final : public Shape {
public:
    Triangle(const Vec3& a, const Vec3& b, const Vec3& c);

    bool intersect(const Ray& ray, double t_min, double t_max, SurfaceHit& hit) const override;
    Aabb bounds() const override;
    bool is_closed() const override { return false; }
    std::optional<FlatPatch> flat_patch() const override;

    const Vec3& vertex(int i) const { return m_v[i]; }
    const Vec3& normal() const { return m_normal; }

private:
    Vec3 m_v[3];
    Vec3 m_normal;
};

}  // namespace lenslab
