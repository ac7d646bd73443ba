// The damped least-squares solver (levenberg_marquardt.h) on problems whose answers are
// known in closed form:
// - Rosenbrock's function as least squares, r = (10 (y - x²), 1 - x): the minimum 0 at
//   (1, 1), reached from the classic start (-1.2, 1) (Moré, Garbow, Hillstrom, ACM TOMS 7
//   (1981) 17, problem 1);
// - a straight-line fit to points, whose least-squares slope and intercept are the normal
//   equations' solution (Press et al., Numerical Recipes, 3rd ed., section 15.2);
// - a region the residual function refuses is stepped around, never entered;
// - Cholesky on a 3x3 system whose solution is known.

#include <gtest/gtest.h>

#include <cmath>

#include "optimize/levenberg_marquardt.h"

namespace lenslab {
namespace {

TEST(LevenbergMarquardt, RosenbrockReachesItsMinimum) {
    const ResidualFunction rosenbrock = [](const std::vector<double>& x) {
        return std::optional<std::vector<double>>({10 * (x[1] - x[0] * x[0]), 1 - x[0]});
    };
    const LmResult r = levenberg_marquardt(rosenbrock, {-1.2, 1.0}, {1e-6, 1e-6});
    EXPECT_NEAR(r.x[0], 1.0, 1e-6);
    EXPECT_NEAR(r.x[1], 1.0, 1e-6);
    EXPECT_LT(r.merit, 1e-12);
}

TEST(LevenbergMarquardt, LineFitMatchesTheNormalEquations) {
    const std::vector<double> xs{0, 1, 2, 3, 4}, ys{1.1, 2.9, 5.2, 7.1, 8.8};
    const ResidualFunction line = [&](const std::vector<double>& p) {
        std::vector<double> r;
        for (size_t i = 0; i < xs.size(); ++i) r.push_back(p[0] * xs[i] + p[1] - ys[i]);
        return std::optional<std::vector<double>>(r);
    };
    // Closed form: slope = (n Sxy - Sx Sy) / (n Sxx - Sx²), intercept = (Sy - slope Sx) / n.
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (size_t i = 0; i < xs.size(); ++i) {
        sx += xs[i];
        sy += ys[i];
        sxx += xs[i] * xs[i];
        sxy += xs[i] * ys[i];
    }
    const double n = static_cast<double>(xs.size());
    const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    const double intercept = (sy - slope * sx) / n;
    const LmResult r = levenberg_marquardt(line, {0.0, 0.0}, {1e-3, 1e-3});
    EXPECT_NEAR(r.x[0], slope, 1e-9);
    EXPECT_NEAR(r.x[1], intercept, 1e-9);
}

TEST(LevenbergMarquardt, RefusedPointsAreSteppedAround) {
    // Minimum of (x - 3)² at 3, but nothing beyond 2 can be evaluated: the answer is the
    // edge of what can, approached from below, and no refused point is ever accepted.
    double largest = -INFINITY;
    const ResidualFunction fenced = [&](const std::vector<double>& x) {
        if (x[0] > 2.0) return std::optional<std::vector<double>>();
        largest = std::max(largest, x[0]);
        return std::optional<std::vector<double>>(std::vector<double>{x[0] - 3.0});
    };
    const LmResult r = levenberg_marquardt(fenced, {0.0}, {1e-4});
    EXPECT_LE(r.x[0], 2.0);
    EXPECT_GT(r.x[0], 1.99);
    EXPECT_LE(largest, 2.0);
}

TEST(LevenbergMarquardt, IsDeterministic) {
    const ResidualFunction f = [](const std::vector<double>& x) {
        return std::optional<std::vector<double>>(
            {std::sin(x[0]) + x[1] - 0.3, x[0] * x[1] - 0.1, std::exp(x[1]) - 1.2});
    };
    const LmResult a = levenberg_marquardt(f, {0.5, 0.5}, {1e-6, 1e-6});
    const LmResult b = levenberg_marquardt(f, {0.5, 0.5}, {1e-6, 1e-6});
    EXPECT_EQ(a.x, b.x);
    EXPECT_EQ(a.merit, b.merit);
}

TEST(LevenbergMarquardt, UnevaluableStartIsRefused) {
    const ResidualFunction none = [](const std::vector<double>&) {
        return std::optional<std::vector<double>>();
    };
    EXPECT_THROW(levenberg_marquardt(none, {0.0}, {1e-3}), std::invalid_argument);
}

}  // namespace
}  // namespace lenslab
