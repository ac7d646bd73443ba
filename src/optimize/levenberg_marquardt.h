#pragma once
// Damped least squares (Levenberg-Marquardt): minimises the sum of squares of a residual
// vector over a few variables, with a Jacobian by central differences and Marquardt's
// damping of the normal equations' diagonal (Marquardt, J. SIAM 11 (1963) 431; Press et
// al., Numerical Recipes, 3rd ed., section 15.5.2). A trial point the model cannot evaluate
// (the residual function returns none: lens faces crossing, rays lost) counts as a step
// that failed: the damping grows and the step shrinks, as for one that made things worse.
// The Jacobian's columns are evaluated in parallel (TBB), each into its own slot, and
// everything else in order, so the result is the same on every run and any number of
// threads; the residual function must be safe to call from several threads at once.

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace lenslab {

// Residuals at a point, or none where the model cannot be evaluated there.
using ResidualFunction =
    std::function<std::optional<std::vector<double>>(const std::vector<double>&)>;

struct LmOptions {
    int max_iterations = 100;
    double initial_damping = 1e-3;
    // Stop when an accepted step lowers the merit by less than this fraction of it.
    double relative_tolerance = 1e-10;
    double max_damping = 1e12;  // a step this damped that still fails: a minimum
};

struct LmProgress {
    int iteration = 0;
    double merit = 0;     // sum of squared residuals after the iteration
    double damping = 0;   // the damping of the accepted step (or the last tried)
    int evaluations = 0;  // residual evaluations so far
};

struct LmResult {
    std::vector<double> x;
    double merit = 0;
    int iterations = 0;
    int evaluations = 0;
    std::string stopped;  // why it stopped, in words
};

// `steps`: the finite-difference step of each variable (its scale). `x0` must be evaluable.
// Throws std::invalid_argument when it is not, or when the sizes disagree.
LmResult levenberg_marquardt(const ResidualFunction& residuals, std::vector<double> x0,
                             const std::vector<double>& steps, const LmOptions& options = {},
                             const std::function<void(const LmProgress&)>& progress = {});

}  // namespace lenslab
