#pragma once
// One refracting surface of a lens, rotationally symmetric about the local +z axis, with its
// vertex at the origin. Its shape is the sag z(r), r = sqrt(x^2 + y^2). Later surface kinds
// (conic, asphere, typed formula) implement this same interface and slot into LensSolid.

#include <string>

#include "geometry/ray.h"

namespace lenslab {

class LensSurface {
public:
    virtual ~LensSurface() = default;

    // Axial height of the surface at radial distance r from the axis.
    virtual double sag(double r) const = 0;
    // Largest radial distance where the surface exists (a sphere of radius R: |R|).
    virtual double max_semi_diameter() const = 0;
    // Nearest crossing of `ray` (in the surface's local frame) with t in (t_min, t_max) and
    // radial distance at most `semi_diameter`.
    virtual bool intersect(const Ray& ray, double semi_diameter, double t_min, double t_max,
                           double& t) const = 0;
    // Unit normal at a point on the surface, with a positive z component.
    virtual Vec3 normal(const Vec3& p) const = 0;
    // Short human-readable form for messages, e.g. "sphere R=50".
    virtual std::string describe() const = 0;
};

// Radial distances within this relative margin of the semi-diameter still count as on the
// surface, so that a ray through the seam between a face and the rim cannot slip through.
inline constexpr double kSeamTolerance = 1e-9;

}  // namespace lenslab
