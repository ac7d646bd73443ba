#pragma once
// A root of a function inside a bracket where it changes sign: Newton's method safeguarded
// by bisection ("rtsafe", Press et al., Numerical Recipes, 3rd ed., section 9.4). Every step
// keeps a sign-change bracket, and a Newton step that would leave it, or that shrinks it too
// slowly, is replaced by bisection, so the iteration converges whatever the starting point.
// A function that jumps across zero without a root converges to the jump: callers that care
// check the value at the result.

#include <cmath>
#include <optional>
#include <utility>

namespace lenslab {

struct ValueAndSlope {
    double value;
    double slope;  // derivative; need not be exact (a finite difference is fine)
};

// `f(t)` returns ValueAndSlope. `fa`, `fb` are f's values at the ends of [a, b] (either
// order). Returns the root to within `tolerance`, or nothing when the ends do not bracket a
// root, a value is NaN, or `max_iterations` pass without convergence.
template <class F>
std::optional<double> bracketed_newton(F&& f, double a, double b, double fa, double fb,
                                       double tolerance, int max_iterations = 200) {
    if (fa == 0.0) return a;
    if (fb == 0.0) return b;
    if (!((fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0))) return std::nullopt;
    // Keep f(lo) < 0 < f(hi); lo may lie above hi.
    double lo = fa < 0.0 ? a : b;
    double hi = fa < 0.0 ? b : a;
    // Start where the chord crosses zero (regula falsi): near the root when f is smooth.
    double x = a - fa * (b - a) / (fb - fa);
    if (!(x > std::min(a, b) && x < std::max(a, b))) x = 0.5 * (a + b);
    double step_before = std::abs(b - a);
    double step = step_before;
    ValueAndSlope v = f(x);
    for (int i = 0; i < max_iterations; ++i) {
        if (std::isnan(v.value)) return std::nullopt;
        if (v.value == 0.0) return x;
        if (v.value < 0.0) {
            lo = x;
        } else {
            hi = x;
        }
        // Newton lands outside (lo, hi), or would not halve the step of two iterations ago:
        // bisect instead.
        const bool newton_leaves =
            ((x - hi) * v.slope - v.value) * ((x - lo) * v.slope - v.value) >= 0.0;
        const bool newton_slow = std::abs(2.0 * v.value) > std::abs(step_before * v.slope);
        step_before = step;
        if (!std::isfinite(v.slope) || v.slope == 0.0 || newton_leaves || newton_slow) {
            step = 0.5 * (hi - lo);
            x = lo + step;
        } else {
            step = v.value / v.slope;
            x -= step;
        }
        if (std::abs(step) <= tolerance) return x;
        v = f(x);
    }
    return std::nullopt;
}

}  // namespace lenslab
