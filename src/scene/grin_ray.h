#pragma once
// A ray through a gradient-index medium, from where it entered the solid to where it leaves:
// the ray equation d/ds (n dr/ds) = grad n, written in the optical-path parameter t
// (dt = ds / n) as Sharma, Kumar and Ghatak (Appl. Opt. 21, 984, 1982) do,
//   dr/dt = T,   dT/dt = n grad n,   T = n dr/ds,
// integrated with the embedded Runge-Kutta 5(4) pair of Dormand and Prince (J. Comput. Appl.
// Math. 6, 19, 1980), its step set by the local error estimate. The last step is shortened
// until it ends on the solid's surface, which is found by intersecting the step's chord.

#include <vector>

#include "geometry/shape.h"
#include "optics/grin_profile.h"

namespace lenslab {

// A profile placed in the scene, its index scaled by `scale` (the dispersion: n(lambda) / n_d).
struct GrinMedium {
    const GrinProfile* profile = nullptr;
    Vec3 centre;
    double scale = 1.0;

    double index(const Vec3& world) const { return scale * profile->index(world - centre); }
    Vec3 gradient(const Vec3& world) const { return profile->gradient(world - centre) * scale; }
};

struct GrinRayOptions {
    double tolerance = 1e-9;  // local error per step, relative to the solid's size
    int max_steps = 100000;   // then the ray is given up (trapped)
};

struct GrinExit {
    bool left = false;  // false: trapped (more than max_steps) or never met the surface
    SurfaceHit hit;     // on the solid's surface; t is the geometric path length inside
    Vec3 direction;     // unit, the ray's direction as it meets the surface from inside
    int steps = 0;      // accepted integration steps
    int rejected = 0;   // steps retried smaller
};

// From `origin` (on or inside `shape`) along unit `direction` through `medium`. `path`, when
// given, receives the points of the accepted steps, from `origin` to the exit point.
GrinExit trace_grin_ray(const GrinMedium& medium, const Shape& shape, const Vec3& origin,
                        const Vec3& direction, const GrinRayOptions& options = {},
                        std::vector<Vec3>* path = nullptr);

}  // namespace lenslab
