#include <gtest/gtest.h>

#include "math/cholesky.h"

namespace lenslab {
namespace {

TEST(Cholesky, SolvesAKnownSystem) {
    // A = [[4, 2, 0], [2, 5, 1], [0, 1, 3]], x = (1, -2, 3): b = A x = (0, -5, 7).
    const std::optional<std::vector<double>> x =
        solve_cholesky({4, 2, 0, 2, 5, 1, 0, 1, 3}, {0, -5, 7});
    ASSERT_TRUE(x);
    EXPECT_NEAR((*x)[0], 1.0, 1e-12);
    EXPECT_NEAR((*x)[1], -2.0, 1e-12);
    EXPECT_NEAR((*x)[2], 3.0, 1e-12);
    EXPECT_FALSE(solve_cholesky({1, 2, 2, 1}, {1, 1}));  // indefinite
}

}  // namespace
}  // namespace lenslab
