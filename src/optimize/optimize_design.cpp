#include "optimize/optimize_design.h"

#include <cmath>

#include "optics/glass.h"
#include "optimize/global_search.h"
#include "optimize/local_search.h"
#include "optimize/model_glass.h"
#include "util/format_number.h"
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

// The lens's model glass as a trial's label: "model 1.62/60.3" (n_d/V_d).
std::string od_model_label(const nlohmann::ordered_json& lens) {
    const nlohmann::ordered_json& ior = lens["material"]["ior"];
    return "model " + format_number(ior["n_d"].get<double>()) + "/" +
           format_number(ior["V_d"].get<double>());
}

// Glass substitution: each lens of a model glass, in the scene's order, given in turn each of
// the catalogue glasses nearest its model on the glass map, the design (without that lens's
// n_d and V_d) re-optimised briefly from there, and the glass that ends lowest kept. A
// catalogue glass must be kept, even where it ends above the model: the lens is to be made.
void od_substitute_glasses(LensDesign& design, ContinuousRun& best, OptimizeResult& result,
                           const std::function<void(const GlassTrial&)>& on_glass) {
    result.model_glass_merit = best.solver.merit;
    for (const DesignLens& lens : design_lenses(best.state.scene)) {
        const nlohmann::ordered_json& object = best.state.scene["objects"][lens.object];
        if (!is_model_glass(object)) continue;
        const nlohmann::ordered_json& ior = object["material"]["ior"];
        result.glass_trials.push_back(
            {lens.name, od_model_label(object), best.solver.merit, false});
        LensDesign without = design;
        std::erase_if(without.variables, [&](const DesignVariable& v) {
            return v.of_glass() && v.object == lens.object;
        });
        std::optional<ContinuousRun> chosen;
        for (const Glass* glass : nearest_catalogue_glasses(
                 ior["n_d"].get<double>(), ior["V_d"].get<double>(),
                 design.glass_substitution.makers, size_t(design.glass_substitution.candidates))) {
            DesignState trial_state = best.state;
            set_lens_catalogue_glass(trial_state.scene, lens.object, *glass);
            GlassTrial trial{lens.name, catalogue_glass_name(*glass), INFINITY, false};
            try {
                const DesignModel trial_model(od_design_at(without, trial_state));
                ContinuousRun run = od_run_continuous(trial_model, design.glass_iterations, {});
                trial.merit = run.solver.merit;
                if (!chosen || run.solver.merit < chosen->solver.merit) chosen = std::move(run);
            } catch (const SceneError&) {
                // This glass cannot make the design work (rays lost at its start): not kept.
            }
            result.glass_trials.push_back(trial);
            if (on_glass) on_glass(trial);
        }
        if (!chosen) {
            throw SceneError("glass_substitution", "no catalogue glass near the model glass of '" +
                                                       lens.name + "' gives a working design");
        }
        const std::string kept = lens_glass(chosen->state.scene, lens.object);
        for (GlassTrial& t : result.glass_trials) {
            if (t.lens == lens.name && t.glass == kept) t.kept = true;
        }
        best = std::move(*chosen);
        design.variables = std::move(without.variables);
    }
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
    for (size_t k = 0; k < design.configurations.size(); ++k) {
        table.configurations.push_back({design.configurations[k].name,
                                        evaluation.configuration_efl[k],
                                        evaluation.configuration_image_distance[k]});
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
    if (!design.configurations.empty() &&
        (!design.glass_choices.empty() || design.glass_substitution.enabled)) {
        throw SceneError(design.glass_choices.empty() ? "glass_substitution" : "glass_choices",
                         "not yet with configurations (the glass passes optimise one)");
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
    // The variables as the design starts (a substituted glass's n_d and V_d after are its
    // catalogue values), and the design as it ends, without them.
    LensDesign final_design = design;
    if (design.glass_substitution.enabled)
        od_substitute_glasses(final_design, best, result, on_glass);
    result.before = merit_table(design, *model.evaluate(x0));
    // A multi-configuration design ends where the solver does (no glass pass changes it).
    const bool configured = !design.configurations.empty();
    if (configured) {
        result.after = merit_table(design, *model.evaluate(best.solver.x));
    } else {
        const DesignModel final_model(od_design_at(final_design, best.state));
        result.after = merit_table(design, *final_model.evaluate(final_model.start()));
    }
    for (size_t i = 0; i < x0.size(); ++i) {
        const DesignVariable& v = design.variables[i];
        double after = 0;
        if (configured) {
            after = best.solver.x[i];
        } else if (v.of_glass() && !is_model_glass(best.state.scene["objects"][v.object])) {
            const Glass* glass = find_glass(lens_glass(best.state.scene, v.object));
            after =
                v.kind == VariableKind::GlassIndex ? glass->datasheet_n_d : glass->datasheet_v_d;
        } else {
            after = variable_value(best.state, v);
        }
        result.variables.push_back({variable_label(v), x0[i], after});
    }
    result.scene = best.state.scene;
    if (configured) {
        const std::vector<DesignState> states = model.configuration_states(best.solver.x);
        for (size_t k = 1; k < states.size(); ++k) {
            result.configuration_scenes.emplace_back(design.configurations[k].name,
                                                     states[k].scene);
        }
    }
    return result;
}

}  // namespace lenslab
