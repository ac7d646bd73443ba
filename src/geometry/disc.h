#pragma once
// A flat disc: an open surface (no inside) given by its centre, normal and radius. Like a
// triangle it is two-sided; its normal is the one given.

#include "geometry/plane_frame.h"
#include "geometry/shape.h"

namespace lenslab {

class Disc final : public Shape {
public:
    // `normal` and `up` unit and not parallel; `up` orients the disc's (u, v) coordinates.
    Disc(const Vec3& centre, const Vec3& normal, double radius, const Vec3& up);

    bool intersect(const Ray& ray, double t_min, double t_max, SurfaceHit& hit) const override;
    Aabb bounds() const override;
    bool is_closed() const override { return false; }
    std::optional<FlatPatch> flat_patch() const override;

    const PlaneFrame& frame() const { return m_frame; }  // origin at the centre
    const Vec3& centre() const { return m_frame.origin; }
    const Vec3& normal() const { return m_frame.n; }
    double radius() const { return m_radius; }

private:
    PlaneFrame m_frame;
    double m_radius;
};

}  // namespace lenslab
