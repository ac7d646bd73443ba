#pragma once
// Where a ray meets a surface given only by its sag z = s(x, y): the first root of
//   g(t) = o_z + t d_z - s(o_x + t d_x, o_y + t d_y)
// in (t_min, t_max), found numerically for aspheres and typed formulas.
//
// 1. Clip: a crossing lies inside the cylinder r <= semi-diameter and the slab
//    z_min <= z <= z_max the sag spans over the disc (SurfaceSpan).
// 2. Bracket: if the ray is steeper than the surface anywhere (|d_z| > max_slope |d_xy|),
//    g is monotone and there is a root iff g changes sign across the clipped segment.
//    Otherwise march from the near end. g is Lipschitz with L = |d_z| + max_slope |d_xy|,
//    so no root lies within |g| / L of a point (sphere tracing, Hart 1996); steps are that
//    long but never shorter than 1/kSagMarchSteps of the diameter (measured across the axis),
//    which bounds the work and is the finest feature a march resolves.
// 3. Refine the first sign change with bracketed Newton (math/bracketed_newton.h) and accept
//    the root only if g is small there: a jump in the sag (a discontinuous formula) brackets
//    no root; the march passes over it, and a ray with no root left reports a miss rather
//    than a wrong hit.

#include <algorithm>
#include <cmath>

#include "geometry/lens/lens_surface.h"
#include "math/bracketed_newton.h"
#include "math/quadratic.h"

namespace lenslab {

// Steps across the diameter of the finest march (see above).
inline constexpr int kSagMarchSteps = 64;

// `Sag` provides `double value(double x, double y)` and
// `double value_and_gradient(double x, double y, double& dz_dx, double& dz_dy)`.
template <class Sag>
bool intersect_sag(const Ray& ray, const SurfaceSpan& span, double t_min, double t_max, double& t,
                   Sag& sag) {
    const Vec3& o = ray.origin;
    const Vec3& d = ray.direction;
    const double a = span.semi_diameter * (1.0 + kSeamTolerance);
    const double dxy2 = d.x * d.x + d.y * d.y;

    // Parallel to the axis: x and y stay put, so z meets the sag there in one step.
    if (dxy2 == 0.0) {
        if (d.z == 0.0 || o.x * o.x + o.y * o.y > a * a) return false;
        const double tc = (sag.value(o.x, o.y) - o.z) / d.z;
        if (!in_range(tc, t_min, t_max)) return false;  // also refuses NaN
        t = tc;
        return true;
    }

    // 1. Clip to the cylinder and the slab.
    double lo = t_min, hi = t_max, c0, c1;
    if (!solve_half_quadratic(dxy2, o.x * d.x + o.y * d.y, o.x * o.x + o.y * o.y - a * a, c0, c1)) {
        return false;
    }
    lo = std::max(lo, c0);
    hi = std::min(hi, c1);
    if (d.z != 0.0) {
        double z0 = (span.z_min - o.z) / d.z, z1 = (span.z_max - o.z) / d.z;
        if (z0 > z1) std::swap(z0, z1);
        lo = std::max(lo, z0);
        hi = std::min(hi, z1);
    } else if (!(o.z >= span.z_min && o.z <= span.z_max)) {
        return false;
    }
    if (!(lo < hi)) return false;

    auto g = [&](double tc) { return o.z + tc * d.z - sag.value(o.x + tc * d.x, o.y + tc * d.y); };
    auto g_and_slope = [&](double tc) {
        double sx, sy;
        const double s = sag.value_and_gradient(o.x + tc * d.x, o.y + tc * d.y, sx, sy);
        return ValueAndSlope{o.z + tc * d.z - s, d.z - sx * d.x - sy * d.y};
    };
    auto changes_sign = [](double g0, double g1) {
        return (g0 > 0.0 && g1 <= 0.0) || (g0 < 0.0 && g1 >= 0.0);
    };
    const double scale = std::max(a, std::abs(lo) + std::abs(hi));
    auto refine = [&](double t0, double t1, double g0, double g1) {
        const auto root = bracketed_newton(g_and_slope, t0, t1, g0, g1, 1e-12 * scale);
        if (!root || !in_range(*root, t_min, t_max)) return false;
        const double residual = g(*root);
        if (!(std::abs(residual) <= 1e-7 * std::max(a, 1e-300))) return false;  // a jump
        t = *root;
        return true;
    };

    // 2. Bracket the first root.
    const double dxy = std::sqrt(dxy2);
    double t0 = lo, g0 = g(lo);
    if (std::abs(d.z) > span.max_slope * dxy) {
        const double g1 = g(hi);
        return changes_sign(g0, g1) && refine(lo, hi, g0, g1);
    }
    const double lipschitz = std::abs(d.z) + span.max_slope * dxy;
    const double min_step = 2.0 * a / kSagMarchSteps / dxy;
    while (t0 < hi) {
        const double safe = std::isfinite(g0) ? std::abs(g0) / lipschitz : 0.0;
        const double t1 = std::min(hi, t0 + std::max(min_step, safe));
        if (!(t1 > t0)) return false;  // the step vanished in rounding
        const double g1 = g(t1);
        // A bracket that holds no root (a jump) is passed over: the march goes on.
        if (changes_sign(g0, g1) && refine(t0, t1, g0, g1)) return true;
        t0 = t1;
        g0 = g1;
    }
    return false;
}

}  // namespace lenslab
