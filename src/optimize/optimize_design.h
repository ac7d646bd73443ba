#pragma once
// Optimises a lens design (lens_design.h) by damped least squares (levenberg_marquardt.h)
// and gives the merit function before and after, operand by operand, with the optimised
// scene to write out.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "optimize/design_evaluation.h"
#include "optimize/global_search.h"
#include "optimize/levenberg_marquardt.h"

namespace lenslab {

struct OperandRow {
    std::string label;
    bool constraint = false;
    double value = 0, target = 0, weight = 0;
    double contribution = 0;  // weight * residual²
};

// A configuration's focal length and image plane (a multi-configuration design's).
struct ConfigurationRow {
    std::string name;
    double efl = 0, image_distance = 0;
};

struct MeritTable {
    double merit = 0;
    double efl = 0, image_distance = 0;  // a multi-configuration design's first configuration's
    std::vector<OperandRow> operands;
    std::vector<ConfigurationRow> configurations;  // empty for one configuration
};

struct VariableRow {
    std::string label;
    double before = 0, after = 0;
};

struct OptimizeResult {
    MeritTable before, after;
    std::vector<VariableRow> variables;
    // The glass pass: per lens with a choice, its glass after the continuous run, then every
    // other glass tried; then per lens of a model glass, its model ("model 1.62/60.3", n_d/V_d)
    // and each catalogue glass tried; `kept` marks the one the result has.
    std::vector<GlassTrial> glass_trials;
    LmResult solver;
    std::optional<GlobalSearchResult> global;  // where the design asked for a global search
    // Where the design substitutes its model glasses: the merit with the model glasses, before
    // the substitution (its trials are among glass_trials).
    std::optional<double> model_glass_merit;
    nlohmann::ordered_json scene;  // the optimised scene (a multi-configuration design's first)
    // A multi-configuration design's other configurations' scenes, by name.
    std::vector<std::pair<std::string, nlohmann::ordered_json>> configuration_scenes;
};

MeritTable merit_table(const LensDesign& design, const DesignEvaluation& evaluation);

// `iterations` overrides the design's when >= 0; `progress` hears of every accepted
// iteration of the continuous run, `on_glass` of every glass tried after it. Throws
// SceneError when the starting design cannot be evaluated.
OptimizeResult optimize_design(const LensDesign& design, int iterations = -1,
                               const std::function<void(const LmProgress&)>& progress = {},
                               const std::function<void(const GlassTrial&)>& on_glass = {});

}  // namespace lenslab
