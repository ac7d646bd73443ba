#include "optimize/optimize_design.h"

namespace lenslab {

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
                               const std::function<void(const LmProgress&)>& progress) {
    const DesignModel model(design);
    const std::vector<double> x0 = model.start();
    std::vector<double> steps;
    for (const DesignVariable& v : design.variables) steps.push_back(variable_step(v));
    LmOptions options;
    options.max_iterations = iterations >= 0 ? iterations : design.iterations;
    const ResidualFunction residuals =
        [&model](const std::vector<double>& x) -> std::optional<std::vector<double>> {
        std::optional<DesignEvaluation> e = model.evaluate(x);
        if (!e) return std::nullopt;
        return std::move(e->residuals);
    };
    OptimizeResult result;
    result.solver = levenberg_marquardt(residuals, x0, steps, options, progress);
    result.before = merit_table(design, *model.evaluate(x0));
    result.after = merit_table(design, *model.evaluate(result.solver.x));
    for (size_t i = 0; i < x0.size(); ++i) {
        result.variables.push_back(
            {variable_label(design.variables[i]), x0[i], result.solver.x[i]});
    }
    result.scene = model.state_at(result.solver.x).scene;
    return result;
}

}  // namespace lenslab
