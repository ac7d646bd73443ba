#pragma once
// Orthonormal frame around a unit vector: turns local directions (z = axis) into world ones.

#include "math/vec3.h"

namespace lenslab {

struct Frame {
    Vec3 u, v, w;  // w is the axis

    // Duff et al. 2017, "Building an Orthonormal Basis, Revisited": branchless and
    // continuous except at w.z = -1 where the sign flips.
    static Frame from_axis(const Vec3& w) {
        const double sign = std::copysign(1.0, w.z);
        const double a = -1.0 / (sign + w.z);
        const double b = w.x * w.y * a;
        return {{1.0 + sign * w.x * w.x * a, sign * b, -sign * w.x},
                {b, sign + w.y * w.y * a, -w.y},
                w};
    }

    Vec3 to_world(const Vec3& local) const { return u * local.x + v * local.y + w * local.z; }
    Vec3 to_local(const Vec3& world) const { return {dot(world, u), dot(world, v), dot(world, w)}; }
};

}  // namespace lenslab
