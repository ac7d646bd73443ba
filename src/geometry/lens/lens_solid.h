#pragma once
// A lens element as a closed solid: front surface, back surface and the cylindrical rim
// (edge) between them. Local frame: +z is the optical axis from the front vertex to the back
// vertex, the origin is the midpoint of the two vertices, and +x is `x_axis` (which matters
// only for faces that are not surfaces of revolution).

#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "geometry/lens/lens_surface.h"
#include "geometry/shape.h"
#include "math/frame.h"

namespace lenslab {

struct LensPrescription {
    Vec3 centre;           // midway between the two vertices
    Vec3 axis;             // unit, front vertex -> back vertex
    double thickness = 0;  // centre thickness (vertex to vertex)
    double diameter = 0;
    std::shared_ptr<const LensSurface> front;
    std::shared_ptr<const LensSurface> back;
    // The local +x direction (projected perpendicular to the axis); zero: any fixed one.
    Vec3 x_axis{};
    // A lens moved by a decentre or tilt from where it was designed to stand: the designed
    // axis and front vertex, which the optical system keeps (zero axis: not moved).
    Vec3 designed_axis{}, designed_vertex{};
};

// The lens's local frame: w along the axis, u along x_axis made perpendicular to it (or
// Duff et al.'s choice when none is given), v = w x u so that (u, v, w) is right-handed.
Frame lens_frame(const LensPrescription& p);

class LensSolid final : public Shape {
public:
    // The prescription must have passed `check_prescription`.
    explicit LensSolid(LensPrescription p);

    struct Problem {
        std::string field;  // thickness, diameter, front, back or x_axis
        std::string reason;
    };
    // Why a prescription cannot make a closed solid, or nothing if it can: a face narrower
    // than the lens, a sag that is not a finite number somewhere on the disc, faces that
    // cross inside the diameter.
    static std::optional<Problem> check_prescription(const LensPrescription& p);

    // The report's lens: two equal spheres of radius R intersecting in a circle of radius h;
    // a symmetric biconvex lens with a knife edge at aperture radius h.
    static LensPrescription symmetric_biconvex(const Vec3& centre, const Vec3& axis,
                                               double curvature_radius, double aperture_radius);

    bool intersect(const Ray& ray, double t_min, double t_max, SurfaceHit& hit) const override;
    Aabb bounds() const override;
    bool is_closed() const override { return true; }
    // Around the cylinder of the lens's diameter between its faces' axial extremes: much
    // tighter than the box of a tilted lens.
    BoundingSphere bounding_sphere() const override;

    // True for points inside or on the solid.
    bool contains(const Vec3& p) const override;

    std::optional<OpticalAxis> optical_axis() const override {
        return OpticalAxis{m_p.centre, m_p.axis, m_p.diameter, m_p.thickness, false};
    }

    const LensPrescription* lens_prescription() const override { return &m_p; }
    std::vector<Vec3> axial_outline(const Vec3& across, int steps) const override;

    const LensPrescription& prescription() const { return m_p; }
    const Frame& frame() const { return m_frame; }
    // Axial positions, in the local frame, of the front and back surfaces at radius r
    // (along +x for faces that are not surfaces of revolution) and at (x, y).
    double front_z(double r) const { return -0.5 * m_p.thickness + m_p.front->sag(r); }
    double back_z(double r) const { return 0.5 * m_p.thickness + m_p.back->sag(r); }
    double front_z(double x, double y) const {
        return -0.5 * m_p.thickness + m_p.front->sag_xy(x, y);
    }
    double back_z(double x, double y) const { return 0.5 * m_p.thickness + m_p.back->sag_xy(x, y); }
    // Smallest axial gap between the faces at the rim.
    double edge_thickness() const;

private:
    bool symmetric() const;

    // The slab the faces lie in, along the local z: what bounds() and bounding_sphere() need,
    // measured when first asked for (the renderer asks; the optical bench never does).
    struct Slab {
        std::once_flag measured;
        double z_lo = 0, z_hi = 0;
    };
    const Slab& slab() const;

    LensPrescription m_p;
    Frame m_frame;
    SurfaceSpan m_front_span, m_back_span;  // intersect_span: what the faces' intersect reads
    std::shared_ptr<Slab> m_slab = std::make_shared<Slab>();  // copies share it
    double m_rim_lo = 0, m_rim_hi = 0;  // the rim's z-range when both faces are symmetric
};

}  // namespace lenslab
