#pragma once
// A mirror: one lens surface (geometry/lens/lens_surface.h: flat, sphere, conic, asphere, a
// typed sag formula) standing alone as an open surface, over a disc of the given diameter
// with an optional central hole (a Cassegrain primary's). Its vertex sits at `vertex`, its
// local +z along `axis`: the side its face looks to, so a surface of positive radius (centre
// of curvature on that side) is concave towards it. Two-sided, like a disc; the normal given
// is the face's (towards `axis` at the vertex).

#include <memory>

#include "geometry/lens/lens_surface.h"
#include "geometry/shape.h"
#include "math/frame.h"

namespace lenslab {

struct MirrorPrescription {
    Vec3 vertex;
    Vec3 axis{0, 0, 1};  // unit
    Vec3 x_axis;         // orients a surface that is not one of revolution; zero: automatic
    std::shared_ptr<const LensSurface> surface;
    double diameter = 0;       // > 0
    double hole_diameter = 0;  // 0 <= hole < diameter
};

class MirrorSurface final : public Shape {
public:
    explicit MirrorSurface(MirrorPrescription p);

    bool intersect(const Ray& ray, double t_min, double t_max, SurfaceHit& hit) const override;
    Aabb bounds() const override { return m_bounds; }
    bool is_closed() const override { return false; }
    std::optional<OpticalAxis> optical_axis() const override {
        return OpticalAxis{m_p.vertex, m_p.axis, m_p.diameter, 0, true};
    }

    const MirrorPrescription* mirror_prescription() const override { return &m_p; }
    // The face as rings x sectors quads between the hole and the rim.
    void for_each_facet(const FacetVisitor& visit) const override;

    const MirrorPrescription& prescription() const { return m_p; }
    const Frame& frame() const { return m_frame; }  // w: the axis
    // The point of the surface at local (x, y), in the scene.
    Vec3 point_at(double x, double y) const;

private:
    MirrorPrescription m_p;
    Frame m_frame;
    SurfaceSpan m_span;
    Aabb m_bounds;
};

}  // namespace lenslab
