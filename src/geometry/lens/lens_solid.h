#pragma once
// A lens element as a closed solid: front surface, back surface and the cylindrical rim
// (edge) between them. Local frame: +z is the optical axis from the front vertex to the back
// vertex, and the origin is the midpoint of the two vertices.

#include <memory>
#include <optional>
#include <string>

#include "geometry/lens/lens_surface.h"
#include "geometry/shape.h"
#include "math/frame.h"

namespace lenslab {

struct LensPrescription {
    Vec3 centre;      // midway between the two vertices
    Vec3 axis;        // unit, front vertex -> back vertex
    double thickness = 0;  // centre thickness (vertex to vertex)
    double diameter = 0;
    std::shared_ptr<const LensSurface> front;
    std::shared_ptr<const LensSurface> back;
};

class LensSolid final : public Shape {
public:
    // The prescription must have passed `check_prescription`.
    explicit LensSolid(LensPrescription p);

    struct Problem {
        std::string field;   // thickness, diameter, front or back
        std::string reason;
    };
    // Why a prescription cannot make a closed solid, or nothing if it can.
    static std::optional<Problem> check_prescription(const LensPrescription& p);

    // The report's lens: two equal spheres of radius R intersecting in a circle of radius h;
    // a symmetric biconvex lens with a knife edge at aperture radius h.
    static LensPrescription symmetric_biconvex(const Vec3& centre, const Vec3& axis,
                                               double curvature_radius, double aperture_radius);

    bool intersect(const Ray& ray, double t_min, double t_max, SurfaceHit& hit) const override;
    Aabb bounds() const override;
    bool is_closed() const override { return true; }

    // True for points inside or on the solid.
    bool contains(const Vec3& p) const;

    const LensPrescription& prescription() const { return m_p; }
    // Axial positions, in the local frame, of the front and back surfaces at radius r.
    double front_z(double r) const { return -0.5 * m_p.thickness + m_p.front->sag(r); }
    double back_z(double r) const { return 0.5 * m_p.thickness + m_p.back->sag(r); }
    double edge_thickness() const;

private:
    LensPrescription m_p;
    Frame m_frame;
};

}  // namespace lenslab
