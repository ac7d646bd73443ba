#pragma once
// Tolerancing of a lens design (`lenslab tolerance DESIGN`, docs/optimizer.md#tolerancing):
// how much the image degrades when the lens is made with errors. Each tolerance (a face's
// radius, a lens's centre thickness, an air gap, a lens's decentre or tilt, a glass's melt)
// is tried alone at both ends (the sensitivity table), then all together at random (a Monte
// Carlo of N trials), each time with the back focus refocused as the compensator. The
// criterion is the polychromatic RMS spot radius or RMS wavefront (the root mean square over
// the design's fields) or the MTF at a frequency (the mean over them). Trials draw from their own
// random stream (seed, trial), so the report is the same whatever the thread count, and in a
// job of MPI ranks (`mpirun -np N lenslab tolerance`) the trials are dealt across the ranks
// and the report is still one process's, byte for byte.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "optimize/lens_design.h"

namespace lenslab {

// One tolerance of the design: a variable of its system and the range made lenses fall in.
struct ToleranceItem {
    DesignVariable variable;  // curvature, thickness or air_gap
    std::string label;        // "radius crown.front ± 0.1"
    double nominal = 0;       // the variable's designed value
    double tolerance = 0;     // ± in mm (of the radius, for a curvature)
    // The variable's value for an error of `e` mm (-tolerance to +tolerance).
    double value_at(double e) const;
};

struct SensitivityRow {
    std::string label;
    double tolerance = 0;
    // The criterion with the error at -tolerance and +tolerance (refocused); none: the lens
    // could not be evaluated there (a face crossing another, rays lost).
    std::optional<double> minus, plus;
};

struct MonteCarloSummary {
    int trials = 0, failed = 0;  // failed: made lenses that could not be evaluated
    double mean = 0, sd = 0, min = 0, max = 0;
    double p50 = 0, p90 = 0, p98 = 0;  // percentiles of the criterion
    std::vector<double> criteria;      // every evaluated trial's, in trial order
};

struct ToleranceReport {
    std::string criterion = "rms_spot";  // rms_spot, rms_wavefront or mtf
    bool higher_is_better = false;       // mtf: the changes below are falls, the percentiles
                                         // and the yield count lenses at or above
    double nominal = 0;                  // the criterion of the design as made exactly
    std::vector<double> nominal_fields;  // its criterion per field
    // The nominal image plane from the last vertex (refocused when the made lenses are).
    double image_distance = 0;
    std::vector<SensitivityRow> rows;
    // The root-sum-square of each row's larger change for the worse: the expected worst case.
    double rss_change = 0;
    // What the table predicts of the Monte Carlo, errors uniform within ± T (E[e²] = T² / 3):
    // to first order its spread, √(Σ ((plus - minus) / 2)² / 3); to second order its mean,
    // √(nominal² + Σ ((minus² + plus²) / 2 - nominal²) / 3) (for an MTF, of 1 - MTF).
    double predicted_sd = 0, predicted_mean = 0;
    MonteCarloSummary monte_carlo;
    bool compensated = true;
};

// The design's tolerances as its `tolerances` block sets them, on every lens of the system.
std::vector<ToleranceItem> tolerance_items(const LensDesign& design);

// Runs the sensitivity table and the Monte Carlo. `progress` (may be empty) is told the trials
// done so far. Throws SceneError when the nominal design cannot be evaluated.
ToleranceReport tolerance_design(const LensDesign& design,
                                 const std::function<void(int done, int of)>& progress = {});

}  // namespace lenslab
