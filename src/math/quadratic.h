#pragma once
// Real roots of a t^2 + 2 h t + c = 0, the form ray-quadric intersection takes.

#include <cmath>
#include <utility>

namespace lenslab {

// Returns false when there is no real root; otherwise t0 <= t1.
// Uses q = -(h + sign(h) sqrt(disc)) to avoid cancellation (Numerical Recipes 5.6).
inline bool solve_half_quadratic(double a, double h, double c, double& t0, double& t1) {
    if (a == 0.0) {
        if (h == 0.0) return false;
        t0 = t1 = -c / (2.0 * h);
        return true;
    }
    const double disc = h * h - a * c;
    if (!(disc >= 0.0)) return false;  // also refuses NaN coefficients
    const double q = -(h + std::copysign(std::sqrt(disc), h));
    if (q == 0.0) {  // h == 0 and disc == 0: double root at 0
        t0 = t1 = 0.0;
        return true;
    }
    t0 = q / a;
    t1 = c / q;
    if (t0 > t1) std::swap(t0, t1);
    return true;
}

}  // namespace lenslab
