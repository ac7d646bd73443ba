#pragma once
// The design file (docs/optimizer.md) the editor's Optimise dialog hands the optimiser: the
// document's scene inline, the lenses on the selected lens's axis, and the dialog's targets.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "analysis/system/optical_system.h"

namespace lenslab::gui {

struct OptimiseChoices {
    double efl_target = 100;
    std::vector<double> fields{0.0};  // degrees
    std::vector<double> wavelengths;  // nm; empty: the F, d and C lines
    double epd = 10;
    int stop = 1;  // counted from 1
    bool vary_curvatures = true;
    bool vary_air_gaps = false;
    // The n_d and V_d of lenses of a model glass (an inline `"ior": {"model": "abbe"}`), and
    // after the optimisation the nearest catalogue glasses put in (docs/optimizer.md).
    bool vary_model_glasses = true;
    bool substitute_glasses = false;
    int iterations = 50;
    int global_starts = 0;  // the design's global_search starts; 0: none
};

// Variables of `system`'s elements (their "objects[i]" paths): both curvatures of each, the
// air gaps between them, a model glass's n_d and V_d; operands: the EFL (weight 100) and each
// field's RMS spot; a global_search block with `global_starts` starts when there are any, a
// glass_substitution block when asked.
nlohmann::json optimise_design_json(const nlohmann::json& scene, const OpticalSystem& system,
                                    const OptimiseChoices& choices);

}  // namespace lenslab::gui
