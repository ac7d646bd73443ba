#pragma once

#include "math/vec3.h"

namespace lenslab {

// A half-line origin + t * direction. The direction need not be unit length for
// intersection, but every ray the renderer makes has a unit direction, so t is a distance.
struct Ray {
    Vec3 origin;
    Vec3 direction;

    Vec3 at(double t) const { return origin + direction * t; }
};

// True when t lies strictly inside (t_min, t_max). Written so that a NaN t is rejected:
// every intersection routine filters its roots through this one test.
inline bool in_range(double t, double t_min, double t_max) { return t > t_min && t < t_max; }

// Relative offset used to leave a surface without re-hitting it: scene units are about 1,
// lens prescriptions about 100, so the offset scales with the coordinates' magnitude.
inline double surface_epsilon(const Vec3& p) {
    const double m = std::max(std::abs(p.x), std::max(std::abs(p.y), std::abs(p.z)));
    return 1e-7 * std::max(1.0, m);
}

}  // namespace lenslab
