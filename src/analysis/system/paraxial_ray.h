#pragma once
// One paraxial ray traced surface by surface (the y-nu trace of Smith, Modern Optical
// Engineering, 4th ed., section 3.3): its height y at each vertex plane and its slope u
// before and after the refraction there. The first-order data (first_order.h) and the
// Seidel sums (seidel.h) are read off two such rays, the marginal and the chief ray.
//
// Signs: y > 0 above the axis; u = dy/dz, > 0 for a ray climbing as it travels along +z.
// Refraction: n' u' = n u - y c (n' - n), c the vertex curvature (> 0: centre at +z).

#include <vector>

#include "analysis/system/optical_system.h"

namespace lenslab {

struct ParaxialRaySurface {
    double y = 0;               // height at the vertex plane
    double u = 0, u_after = 0;  // slope before and after the refraction
    double n = 1, n_after = 1;  // indices before and after
};

struct ParaxialRay {
    double y0 = 0, u0 = 0;  // in object space, at the plane of the first vertex (z = 0)
    std::vector<ParaxialRaySurface> surfaces;

    const ParaxialRaySurface& last() const { return surfaces.back(); }
    // Height in image space at axial position z (system coordinates).
    double height_after(const OpticalSystem& system, double z) const;
    // Height in object space at axial position z.
    double height_before(double z) const { return y0 + u0 * z; }
};

// Traces the ray that crosses the plane z = 0 at height y0 with slope u0 in object space.
ParaxialRay trace_paraxial_ray(const OpticalSystem& system, double wavelength_nm, double y0,
                               double u0);

// The ray a * r1 + b * r2: the trace is linear in (y0, u0), so rays combine.
ParaxialRay combine_rays(double a, const ParaxialRay& r1, double b, const ParaxialRay& r2);

}  // namespace lenslab
