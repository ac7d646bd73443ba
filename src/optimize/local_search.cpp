#include "optimize/local_search.h"

#include <algorithm>
#include <cmath>

namespace lenslab {

double bounded_from_internal(const DesignVariable& v, double u) {
    if (!v.bounded()) return u;
    return *v.min + (*v.max - *v.min) * 0.5 * (1.0 + std::sin(u));
}

double internal_from_bounded(const DesignVariable& v, double x) {
    if (!v.bounded()) return x;
    const double s = 2.0 * (std::clamp(x, *v.min, *v.max) - *v.min) / (*v.max - *v.min) - 1.0;
    return std::asin(std::clamp(s, -1.0, 1.0));
}

LmResult local_search(const DesignModel& model, const std::vector<double>& x0, int iterations,
                      const std::function<void(const LmProgress&)>& progress) {
    const std::vector<DesignVariable>& variables = model.design().variables;
    std::vector<double> u0(x0.size()), steps(x0.size());
    for (size_t i = 0; i < x0.size(); ++i) {
        const DesignVariable& v = variables[i];
        u0[i] = internal_from_bounded(v, x0[i]);
        // In u, the step that moves x by about its own step in the middle of the range
        // (dx/du = (max - min) / 2 there).
        steps[i] = v.bounded() ? variable_step(v) / (0.5 * (*v.max - *v.min)) : variable_step(v);
    }
    const auto external = [&variables](const std::vector<double>& u) {
        std::vector<double> x(u.size());
        for (size_t i = 0; i < u.size(); ++i) x[i] = bounded_from_internal(variables[i], u[i]);
        return x;
    };
    const ResidualFunction residuals =
        [&model, &external](const std::vector<double>& u) -> std::optional<std::vector<double>> {
        std::optional<DesignEvaluation> e = model.evaluate(external(u));
        if (!e) return std::nullopt;
        return std::move(e->solver_residuals);
    };
    LmOptions options;
    options.max_iterations = iterations;
    LmResult result = levenberg_marquardt(residuals, u0, steps, options, progress);
    result.x = external(result.x);
    return result;
}

}  // namespace lenslab
