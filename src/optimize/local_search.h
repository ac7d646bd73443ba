#pragma once
// The local optimisation of a design from one point: damped least squares
// (levenberg_marquardt.h) on the design's residuals, with the variables that have bounds
// (`min`, `max`) changed into unbounded ones by the sine transform
//     x = min + (max - min) (1 + sin u) / 2,
// as MINUIT does (F. James and M. Roos, Comput. Phys. Commun. 10 (1975) 343; the MINUIT
// manual, "Parameter limits"): the solver moves u freely and x never leaves [min, max].

#include <functional>
#include <vector>

#include "optimize/design_evaluation.h"
#include "optimize/levenberg_marquardt.h"

namespace lenslab {

// Bounded value x from the solver's u, and back (x clamped into its bounds first).
double bounded_from_internal(const DesignVariable& v, double u);
double internal_from_bounded(const DesignVariable& v, double x);

// At most `iterations` iterations from `x0` (the design's variables, within their bounds);
// the result's `x` is in the design's variables too. Throws std::invalid_argument when `x0`
// cannot be evaluated.
LmResult local_search(const DesignModel& model, const std::vector<double>& x0, int iterations,
                      const std::function<void(const LmProgress&)>& progress = {});

}  // namespace lenslab
