#pragma once
// The global search of `lenslab optimize` (docs/optimizer.md#global-search): damped least
// squares finds the valley nearest its start, so the search starts it from many points spread
// evenly over the variables' region (a Halton sequence in the first primes, rotated by the
// seed: Cranley-Patterson), runs each a few iterations, and polishes the best few with the
// design's whole iteration count. The design's own start is always the first point.
// Curvatures without bounds are drawn within +-1 / (2 semi-diameter) (no face steeper than a
// radius of twice the lens's semi-diameter); other variables without bounds keep their
// starting values in the starts (the solver still moves them).
//
// Every start is its own task and its result is kept in its own slot; the ranking breaks ties
// by start index: the result is the same at any number of threads. In a job of MPI ranks
// (`mpirun -np N lenslab optimize`) start k and polish run j go to rank k (j) mod N and the
// runs are shared, bit for bit: every rank ends with one process's result.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "optimize/design_evaluation.h"
#include "optimize/levenberg_marquardt.h"

namespace lenslab {

struct GlobalSearchStart {
    int index = 0;                     // 0: the design's own start
    std::vector<double> x;             // where it started
    bool evaluable = false;            // rays lost or faces crossing there: not tried
    double merit = INFINITY;           // after the short run
    double polished_merit = INFINITY;  // after the whole run; only the polished
    bool polished = false;
};

struct GlobalSearchResult {
    std::vector<GlobalSearchStart> starts;
    int chosen = 0;       // the start whose polished result is kept
    LmResult solver;      // the chosen start's whole run (x in the design's variables)
    int evaluations = 0;  // all runs together
};

// The region a variable's starts are drawn from: [lo, hi], or lo == hi where it is not drawn.
struct SearchRange {
    double lo = 0, hi = 0;
};
std::vector<SearchRange> search_ranges(const DesignModel& model);

// The most runs `progress` hears of: every start's short run, then the polished ones (fewer
// where fewer starts could be evaluated).
inline int global_search_runs(const GlobalSearchSettings& s) {
    return s.starts + std::min(s.starts, s.keep);
}

// `progress` hears of each run as it ends (the starts' short runs, then the polished ones):
// `iteration` counts the runs ended (starts + kept in all), `merit` is the lowest so far. It
// is called from the worker threads, one call at a time; an exception from it stops the
// search and reaches the caller. Throws SceneError when the design's own start cannot be
// evaluated.
GlobalSearchResult global_search(const DesignModel& model, const GlobalSearchSettings& settings,
                                 int iterations,
                                 const std::function<void(const LmProgress&)>& progress = {});

}  // namespace lenslab
