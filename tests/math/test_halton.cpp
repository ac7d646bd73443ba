// The Halton sequence: radical inverses written out by hand, and the rotation modulo 1.

#include <gtest/gtest.h>

#include "math/halton.h"

namespace lenslab {
namespace {

TEST(Halton, RadicalInversesMirrorTheDigits) {
    // 6 = 110 in base 2 -> 0.011 = 3/8; 5 = 12 in base 3 -> 0.21 = 2/3 + 1/9 = 7/9;
    // 7 = 12 in base 5 -> 0.21 = 2/5 + 1/25; 50 = 101 in base 7 -> 0.101 = 1/7 + 1/343;
    // 12 = 11 in base 11 -> 0.11 = 1/11 + 1/121.
    EXPECT_DOUBLE_EQ(radical_inverse(0, 6), 0.375);
    EXPECT_DOUBLE_EQ(radical_inverse(1, 5), 7.0 / 9.0);
    EXPECT_DOUBLE_EQ(radical_inverse(2, 7), 2.0 / 5.0 + 1.0 / 25.0);
    EXPECT_DOUBLE_EQ(radical_inverse(3, 50), 1.0 / 7.0 + 1.0 / 343.0);
    EXPECT_DOUBLE_EQ(radical_inverse(4, 12), 1.0 / 11.0 + 1.0 / 121.0);
    EXPECT_EQ(radical_inverse(2, 0), 0.0);
}

TEST(Halton, TheFirstPointsOfBaseTwoHalveEveryInterval) {
    // Van der Corput: 1/2, 1/4, 3/4, 1/8, 5/8, 3/8, 7/8.
    const double expected[] = {0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875};
    for (uint64_t i = 1; i <= 7; ++i) EXPECT_DOUBLE_EQ(radical_inverse(0, i), expected[i - 1]);
}

TEST(Halton, RotationWrapsAroundOne) {
    const std::array<double, kHaltonDimensions> rotation = {0.75, 0.0, 0.5, 0.25, 0.95, 0.9};
    const auto u = halton_point(1, rotation);  // (1/2, 1/3, 1/5, 1/7, 1/11, 1/13) before rotation
    EXPECT_DOUBLE_EQ(u[0], 0.25);
    EXPECT_DOUBLE_EQ(u[1], 1.0 / 3.0);
    EXPECT_DOUBLE_EQ(u[2], 0.7);
    EXPECT_DOUBLE_EQ(u[3], 1.0 / 7.0 + 0.25);
    EXPECT_NEAR(u[4], 1.0 / 11.0 + 0.95 - 1.0, 1e-15);
    EXPECT_NEAR(u[5], 1.0 / 13.0 + 0.9, 1e-15);
    for (double x : u) {
        EXPECT_GE(x, 0.0);
        EXPECT_LT(x, 1.0);
    }
}

}  // namespace
}  // namespace lenslab
