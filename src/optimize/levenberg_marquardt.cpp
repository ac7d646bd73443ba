#include "optimize/levenberg_marquardt.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <stdexcept>

#include "math/cholesky.h"

namespace lenslab {

namespace {

double lm_sum_of_squares(const std::vector<double>& r) {
    double sum = 0;
    for (double v : r) sum += v * v;
    return sum;
}

// Column j of the Jacobian by central differences; one-sided where one side cannot be
// evaluated, zero where neither can (the variable then does not move this iteration).
std::vector<double> lm_jacobian_column(const ResidualFunction& residuals, std::vector<double> x,
                                       const std::vector<double>& r0, size_t j, double h) {
    const double xj = x[j];
    x[j] = xj + h;
    const std::optional<std::vector<double>> plus = residuals(x);
    x[j] = xj - h;
    const std::optional<std::vector<double>> minus = residuals(x);
    std::vector<double> column(r0.size(), 0.0);
    for (size_t i = 0; i < r0.size(); ++i) {
        if (plus && minus) {
            column[i] = ((*plus)[i] - (*minus)[i]) / (2 * h);
        } else if (plus) {
            column[i] = ((*plus)[i] - r0[i]) / h;
        } else if (minus) {
            column[i] = (r0[i] - (*minus)[i]) / h;
        }
    }
    return column;
}

}  // namespace

LmResult levenberg_marquardt(const ResidualFunction& residuals, std::vector<double> x0,
                             const std::vector<double>& steps, const LmOptions& options,
                             const std::function<void(const LmProgress&)>& progress) {
    if (steps.size() != x0.size()) {
        throw std::invalid_argument("levenberg_marquardt: one step per variable");
    }
    std::optional<std::vector<double>> r = residuals(x0);
    if (!r) throw std::invalid_argument("levenberg_marquardt: the start cannot be evaluated");
    LmResult result;
    result.x = std::move(x0);
    result.merit = lm_sum_of_squares(*r);
    result.evaluations = 1;
    const size_t n = result.x.size(), m = r->size();
    double damping = options.initial_damping;
    if (n == 0) {
        result.stopped = "no variables";
        return result;
    }
    for (int iteration = 1; iteration <= options.max_iterations; ++iteration) {
        // The columns in parallel: each is computed alone and stored in its own slot, so the
        // Jacobian is the same bit for bit whatever the number of threads.
        std::vector<std::vector<double>> jacobian(n);
        tbb::parallel_for(size_t{0}, n, [&](size_t j) {
            jacobian[j] = lm_jacobian_column(residuals, result.x, *r, j, steps[j]);
        });
        result.evaluations += static_cast<int>(2 * n);
        // Normal equations J^T J d = -J^T r.
        std::vector<double> jtj(n * n, 0.0), jtr(n, 0.0);
        for (size_t a = 0; a < n; ++a) {
            for (size_t i = 0; i < m; ++i) jtr[a] -= jacobian[a][i] * (*r)[i];
            for (size_t b = 0; b <= a; ++b) {
                double s = 0;
                for (size_t i = 0; i < m; ++i) s += jacobian[a][i] * jacobian[b][i];
                jtj[a * n + b] = jtj[b * n + a] = s;
            }
        }
        // In units of each variable's step (its natural scale), the mean diagonal of J^T J:
        // damping in proportion to it too holds back a variable that barely acts on the
        // residuals, which Marquardt's damping alone would let run far (an air gap in a
        // system of little power).
        double mean_scaled = 0;
        for (size_t j = 0; j < n; ++j) mean_scaled += jtj[j * n + j] * steps[j] * steps[j] / n;
        if (!(mean_scaled > 0)) mean_scaled = 1e-30;
        bool accepted = false;
        while (!accepted && damping <= options.max_damping) {
            std::vector<double> a = jtj;
            // Marquardt: damp each diagonal element in proportion to itself, so the step
            // does not depend on the variables' units.
            for (size_t j = 0; j < n; ++j) {
                a[j * n + j] += damping * (jtj[j * n + j] + mean_scaled / (steps[j] * steps[j]));
            }
            const std::optional<std::vector<double>> step = solve_cholesky(a, jtr);
            if (step) {
                std::vector<double> trial = result.x;
                for (size_t j = 0; j < n; ++j) trial[j] += (*step)[j];
                std::optional<std::vector<double>> rt = residuals(trial);
                ++result.evaluations;
                const double merit = rt ? lm_sum_of_squares(*rt) : INFINITY;
                if (merit < result.merit) {
                    const double gain = result.merit - merit;
                    result.x = std::move(trial);
                    r = std::move(rt);
                    const double before = result.merit;
                    result.merit = merit;
                    damping = std::max(damping * 0.2, 1e-15);
                    accepted = true;
                    result.iterations = iteration;
                    if (progress) {
                        progress({iteration, result.merit, damping, result.evaluations});
                    }
                    if (gain <= options.relative_tolerance * before || result.merit == 0) {
                        result.stopped = "converged (the merit stopped falling)";
                        return result;
                    }
                    continue;
                }
            }
            damping *= 10;
        }
        if (!accepted) {
            result.stopped = "converged (no step lowers the merit)";
            return result;
        }
    }
    result.stopped = "iteration limit reached";
    return result;
}

}  // namespace lenslab
