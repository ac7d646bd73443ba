#include "optimize/optimize_design.h"

#include <cmath>

#include "optimize/global_search.h"
#include "optimize/local_search.h"
#include "util/scene_error.h"

namespace lenslab {

namespace {

// The continuous optimisation of `design` from its own scene: the solver's result and the
// state it ends in.
struct ContinuousRun {
    LmResult solver;
    DesignState state;
};

ContinuousRun od_run_continuous(const DesignModel& model, int iterations,
                                const std::function<void(const LmProgress&)>& progress) {
    ContinuousRun run;
    run.solver = local_search(model, model.start(), iterations, progress);
    run.state = model.state_at(run.solver.x);
    return run;
}

// `design` starting from `state` instead of its own scene.
LensDesign od_design_at(const LensDesign& design, const DesignState& state) {
    LensDesign moved = design;
    moved.scene = state.scene;
    if (moved.image_distance) moved.image_distance = state.image_distance;
    return moved;
}

}  // namespace

MeritTable merit_table(const LensDesign& design, const DesignEvaluation& evaluation) {
    MeritTable table;
    table.merit = evaluation.merit;
    table.efl = evaluation.efl;
    table.image_distance = evaluation.image_distance;
    for (size_t i = 0; i < design.operands.size(); ++i) {
        const MeritOperand& op = design.operands[i];
        table.operands.push_back({operand_label(op), is_constraint(op), evaluation.values[i],
                                  op.target, op.weight,
                                  evaluation.residuals[i] * evaluation.residuals[i]});
    }
    return table;
}

OptimizeResult optimize_design(const LensDesign& design, int iterations,
                               const std::function<void(const LmProgress&)>& progress,
                               const std::function<void(const GlassTrial&)>& on_glass) {
    if (design.operands.empty()) {
        throw SceneError("operands",
                         "missing (required: the merit function lenslab optimize "
                         "minimises)");
    }
    const DesignModel model(design);
    const std::vector<double> x0 = model.start();
    OptimizeResult result;
    const int whole = iterations >= 0 ? iterations : design.iterations;
    ContinuousRun best;
    if (design.global_search.starts > 0) {
        GlobalSearchResult global = global_search(model, design.global_search, whole, progress);
        best.solver = global.solver;
        best.state = model.state_at(global.solver.x);
        result.global = std::move(global);
    } else {
        best = od_run_continuous(model, whole, progress);
    }
    result.solver = best.solver;
    for (const GlassChoice& choice : design.glass_choices) {
        const std::string current = lens_glass(best.state.scene, choice.object);
        result.glass_trials.push_back({choice.lens, current, best.solver.merit, true});
        for (const std::string& glass : choice.glasses) {
            if (glass == current) continue;
            DesignState trial_state = best.state;
            set_lens_glass(trial_state.scene, choice.object, glass);
            GlassTrial trial{choice.lens, glass, INFINITY, false};
            try {
                const DesignModel trial_model(od_design_at(design, trial_state));
                ContinuousRun run = od_run_continuous(trial_model, design.glass_iterations, {});
                trial.merit = run.solver.merit;
                if (run.solver.merit < best.solver.merit) {
                    for (GlassTrial& t : result.glass_trials) {
                        if (t.lens == choice.lens) t.kept = false;
                    }
                    trial.kept = true;
                    best = std::move(run);
                }
            } catch (const SceneError&) {
                // This glass cannot make the design work (rays lost at its start): not kept.
            }
            result.glass_trials.push_back(trial);
            if (on_glass) on_glass(trial);
        }
    }
    const DesignModel final_model(od_design_at(design, best.state));
    result.before = merit_table(design, *model.evaluate(x0));
    result.after = merit_table(design, *final_model.evaluate(final_model.start()));
    const std::vector<double> x_after = final_model.start();
    for (size_t i = 0; i < x0.size(); ++i) {
        result.variables.push_back({variable_label(design.variables[i]), x0[i], x_after[i]});
    }
    result.scene = best.state.scene;
    return result;
}

}  // namespace lenslab
