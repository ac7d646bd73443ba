#pragma once

#include "geometry/shape.h"

namespace lenslab {

class Sphere final : public Shape {
public:
    Sphere(const Vec3& centre, double radius) : m_centre(centre), m_radius(radius) {}

    bool intersect(const Ray& ray, double t_min, double t_max, SurfaceHit& hit) const override;
    Aabb bounds() const override;
    bool is_closed() const override { return true; }
    bool contains(const Vec3& p) const override {
        return length_squared(p - m_centre) <= m_radius * m_radius;
    }
    BoundingSphere bounding_sphere() const override { return {m_centre, m_radius}; }
    std::optional<BoundingSphere> exact_sphere() const override { return bounding_sphere(); }

    const Vec3& centre() const { return m_centre; }
    double radius() const { return m_radius; }

private:
    Vec3 m_centre;
    double m_radius;
};

}  // namespace lenslab
