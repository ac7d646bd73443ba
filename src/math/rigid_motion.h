#pragma once
// A decentre and tilts as a rigid motion of space (Zemax's coordinate break with order 0):
// across an axis frame by (decenter_x, decenter_y), then turned about the frame's x, the
// turned y and the turned z through a pivot, each turn about the axes the previous one left.
// Lens group elements and lenses moved from the axis they were designed on use it.

#include <cmath>

#include "math/frame.h"
#include "math/vec3.h"

namespace lenslab {

// Turns v about the unit axis k by `angle` radians, right-handed (Rodrigues' formula).
inline Vec3 turned(const Vec3& v, const Vec3& k, double angle) {
    return v * std::cos(angle) + cross(k, v) * std::sin(angle) +
           k * (dot(k, v) * (1.0 - std::cos(angle)));
}

struct Decentring {
    double decenter_x = 0, decenter_y = 0;      // across the frame's u and v
    double tilt_x = 0, tilt_y = 0, tilt_z = 0;  // degrees

    bool moves() const {
        return decenter_x != 0 || decenter_y != 0 || tilt_x != 0 || tilt_y != 0 || tilt_z != 0;
    }
};

struct RigidMotion {
    Vec3 pivot, shift;
    Frame from;  // the frame the motion is given in
    Frame to;    // where its u, v and w go

    Vec3 point(const Vec3& p) const { return pivot + shift + direction(p - pivot); }
    Vec3 direction(const Vec3& d) const {
        return to.u * dot(d, from.u) + to.v * dot(d, from.v) + to.w * dot(d, from.w);
    }
};

inline RigidMotion rigid_motion(const Decentring& d, const Vec3& pivot, const Frame& f) {
    const double degree = M_PI / 180.0;
    Frame axes = f;
    const auto turn = [&axes](const Vec3& hinge, double angle) {
        const Vec3 k = hinge;  // copied: turning the axes moves the hinge with them
        axes = {turned(axes.u, k, angle), turned(axes.v, k, angle), turned(axes.w, k, angle)};
    };
    turn(axes.u, d.tilt_x * degree);
    turn(axes.v, d.tilt_y * degree);
    turn(axes.w, d.tilt_z * degree);
    return {pivot, f.u * d.decenter_x + f.v * d.decenter_y, f, axes};
}

}  // namespace lenslab
