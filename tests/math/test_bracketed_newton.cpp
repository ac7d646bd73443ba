// Safeguarded Newton: converges inside a bracket, refuses what is not one, and never leaves.

#include <gtest/gtest.h>

#include <cmath>

#include "math/bracketed_newton.h"

namespace lenslab {
namespace {

TEST(BracketedNewton, FindsTheRootOfASmoothFunction) {
    // cos x = x at x = 0.7390851332151607 (the Dottie number).
    int calls = 0;
    auto f = [&](double x) {
        ++calls;
        return ValueAndSlope{std::cos(x) - x, -std::sin(x) - 1.0};
    };
    const auto root = bracketed_newton(f, 0.0, 1.0, f(0.0).value, f(1.0).value, 1e-14);
    ASSERT_TRUE(root);
    EXPECT_NEAR(*root, 0.7390851332151607, 1e-14);
    EXPECT_LT(calls, 12);  // Newton's quadratic convergence, not bisection's 47 halvings
}

TEST(BracketedNewton, AWrongSlopeOnlySlowsItDown) {
    // A derivative off by a factor of 10 still converges (bisection takes over).
    auto f = [](double x) { return ValueAndSlope{x * x * x - 2.0, 30.0 * x * x}; };
    const auto root = bracketed_newton(f, 0.0, 2.0, -2.0, 6.0, 1e-13);
    ASSERT_TRUE(root);
    EXPECT_NEAR(*root, std::cbrt(2.0), 1e-12);
}

TEST(BracketedNewton, RefusesWhatIsNotABracket) {
    auto f = [](double x) { return ValueAndSlope{x * x + 1.0, 2.0 * x}; };
    EXPECT_FALSE(bracketed_newton(f, -1.0, 1.0, 2.0, 2.0, 1e-12));
    auto nan = [](double) { return ValueAndSlope{NAN, 0.0}; };
    EXPECT_FALSE(bracketed_newton(nan, 0.0, 1.0, -1.0, 1.0, 1e-12));
}

TEST(BracketedNewton, AJumpConvergesToTheJumpNotBeyondIt) {
    // sign(x - 0.3) has no root; the result stays in the bracket at the jump, and its value
    // there is far from zero, which is how callers tell a jump from a root.
    auto f = [](double x) { return ValueAndSlope{x < 0.3 ? -1.0 : 1.0, 0.0}; };
    const auto root = bracketed_newton(f, 0.0, 1.0, -1.0, 1.0, 1e-12);
    ASSERT_TRUE(root);
    EXPECT_NEAR(*root, 0.3, 1e-11);
}

}  // namespace
}  // namespace lenslab
