#include <gtest/gtest.h>

#include <cmath>

#include "geometry/sphere.h"

namespace lenslab {
namespace {

TEST(Sphere, HitFromOutsideHandComputed) {
    const Sphere s({0, 0, 0}, 1.0);
    SurfaceHit h;
    ASSERT_TRUE(s.intersect({{0, 0, -5}, {0, 0, 1}}, 0, INFINITY, h));
    EXPECT_DOUBLE_EQ(h.t, 4.0);
    EXPECT_NEAR(h.normal.z, -1.0, 1e-15);
    // Off-axis: y = 0.6 meets the unit sphere at z = -0.8, normal (0, 0.6, -0.8).
    ASSERT_TRUE(s.intersect({{0, 0.6, -5}, {0, 0, 1}}, 0, INFINITY, h));
    EXPECT_NEAR(h.t, 4.2, 1e-14);
    EXPECT_NEAR(h.normal.y, 0.6, 1e-14);
    EXPECT_NEAR(h.normal.z, -0.8, 1e-14);
}

TEST(Sphere, HitFromInsideFindsTheExitWithOutwardNormal) {
    const Sphere s({1, 2, 3}, 2.0);
    SurfaceHit h;
    ASSERT_TRUE(s.intersect({{1, 2, 3}, {1, 0, 0}}, 1e-9, INFINITY, h));
    EXPECT_DOUBLE_EQ(h.t, 2.0);
    EXPECT_NEAR(h.normal.x, 1.0, 1e-15);
}

TEST(Sphere, MissesAndRespectsTheInterval) {
    const Sphere s({0, 0, 0}, 1.0);
    SurfaceHit h;
    EXPECT_FALSE(s.intersect({{0, 1.01, -5}, {0, 0, 1}}, 0, INFINITY, h));
    EXPECT_FALSE(s.intersect({{0, 0, -5}, {0, 0, 1}}, 0, 3.9, h));
    EXPECT_FALSE(s.intersect({{0, 0, 5}, {0, 0, 1}}, 0, INFINITY, h));  // sphere behind
}

TEST(Sphere, GrazingRayGivesAFiniteTangentHit) {
    const Sphere s({0, 0, 0}, 1.0);
    SurfaceHit h;
    if (s.intersect({{0, 1.0, -5}, {0, 0, 1}}, 0, INFINITY, h)) {
        EXPECT_NEAR(h.t, 5.0, 1e-6);
        EXPECT_TRUE(is_finite(h.normal));
    }
}

}  // namespace
}  // namespace lenslab
