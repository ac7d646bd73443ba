#pragma once
// A flat rectangle: an open surface (no inside) given by its centre, normal, size and which
// way its height runs (`up`). Two-sided like a triangle; its normal is the one given.

#include "geometry/plane_frame.h"
#include "geometry/shape.h"

namespace lenslab {

class Rectangle final : public Shape {
public:
    // `width` runs along the frame's u = up x normal, `height` along v; `normal` and `up`
    // unit and not parallel.
    Rectangle(const Vec3& centre, const Vec3& normal, double width, double height, const Vec3& up);

    bool intersect(const Ray& ray, double t_min, double t_max, SurfaceHit& hit) const override;
    Aabb bounds() const override;
    bool is_closed() const override { return false; }
    std::optional<FlatPatch> flat_patch() const override;

    const PlaneFrame& frame() const { return m_frame; }  // origin at the centre
    const Vec3& centre() const { return m_frame.origin; }
    const Vec3& normal() const { return m_frame.n; }
    double width() const { return m_width; }
    double height() const { return m_height; }

private:
    PlaneFrame m_frame;
    double m_width, m_height;
};

}  // namespace lenslab
