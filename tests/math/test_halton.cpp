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

// The constant-base radical inverses, taken a block of digits at a time, against the digit by
// digit definition, over the indices a render uses and past the exact range (a fallback).
TEST(Halton, BlocksOfDigitsGiveTheDigitByDigitValues) {
    const uint64_t primes[] = {2, 3, 5, 7, 11, 13};
    for (int d = 0; d < kHaltonDimensions; ++d) {
        for (uint64_t i : {uint64_t{0}, uint64_t{1}, uint64_t{1023}, uint64_t{1024},
                           uint64_t{123457}, uint64_t{1} << 40, (uint64_t{1} << 62) + 12345}) {
            EXPECT_NEAR(radical_inverse(d, i), radical_inverse_of(primes[d], i), 1e-15)
                << "base " << primes[d] << ", index " << i;
            EXPECT_LT(radical_inverse(d, i), 1.0);
        }
        for (uint64_t i = 0; i < 200000; i += 7) {
            ASSERT_NEAR(radical_inverse(d, i), radical_inverse_of(primes[d], i), 1e-15)
                << "base " << primes[d] << ", index " << i;
        }
    }
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
