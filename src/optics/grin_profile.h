#pragma once
// A gradient-index (GRIN) medium: the refractive index as a function of position, with its
// gradient, for the ray equation d/ds (n dr/ds) = grad n (optics/grin_ray.h).
//
// The profile lives in its own frame: `centre` (the centre of the object it fills unless the
// material says otherwise) and the unit `axis`. With p the point relative to the centre,
// r = |p|, z = p . axis and rho the distance of p from the axis:
//   luneburg  n = sqrt(2 - (r/R)^2)        (Luneburg 1944: focuses a parallel beam on the rim)
//   fisheye   n = n0 / (1 + (r/R)^2)       (Maxwell 1854: images a point to its antipode)
//   radial    n = n0 (1 - A rho^2 / 2)     (a GRIN rod, pitch 2 pi / sqrt(A) near the axis)
//   axial     n = n0 + A z                 (a linear gradient along the axis)
//   formula   n = f(x, y, z), x, y, z = p  (muparser; gradient by central differences)
// The first four have analytic gradients.

#include <memory>
#include <optional>
#include <string>

#include "math/formula.h"
#include "math/vec3.h"

namespace lenslab {

enum class GrinKind { Luneburg, Fisheye, Radial, Axial, Formula };

const char* grin_kind_name(GrinKind kind);

struct GrinProfile {
    GrinKind kind = GrinKind::Luneburg;
    double n0 = 1.0;                         // fisheye, radial, axial
    double A = 0.0;                          // radial: per unit^2; axial: per unit
    double radius = 1.0;                     // luneburg, fisheye
    std::shared_ptr<const Formula> formula;  // formula
    std::string owner;                       // the JSON path, for errors of the formula
    bool has_centre = false;                 // else the object's centre
    Vec3 centre;
    Vec3 axis{0, 0, 1};

    // Index and gradient at `p`, relative to the profile's centre.
    double index(const Vec3& p) const;
    Vec3 gradient(const Vec3& p) const;

    // Why the index is no medium somewhere in the box [lo, hi] (world coordinates, the
    // profile centred at `origin`): not a number or not > 0 at a point of a 9^3 grid, e.g. a
    // radial profile whose A makes n negative at the rim. Nothing when it is one.
    std::optional<std::string> problem_in(const Vec3& origin, const Vec3& lo, const Vec3& hi) const;
};

// The formula's variables, as implicit solids name them.
inline const char* const kGrinFormulaHint = "(a GRIN index is a function of x, y and z)";

}  // namespace lenslab
