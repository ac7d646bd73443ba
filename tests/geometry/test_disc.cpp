// A disc: an open flat surface hit inside its radius from either side, missed outside.

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/disc.h"

namespace lenslab {
namespace {

TEST(Disc, HitInsideTheRadiusFromEitherSide) {
    const Disc disc({1, 2, 3}, {0, 0, 1}, 0.5, {0, 1, 0});
    SurfaceHit h;
    ASSERT_TRUE(disc.intersect({{1.3, 2.3, 5}, {0, 0, -1}}, 0, INFINITY, h));
    EXPECT_DOUBLE_EQ(h.t, 2.0);
    EXPECT_NEAR(h.point.x, 1.3, 1e-15);
    EXPECT_EQ(h.normal.z, 1.0);  // the normal given, whichever side the ray comes from
    ASSERT_TRUE(disc.intersect({{1.3, 2.3, 0}, {0, 0, 1}}, 0, INFINITY, h));
    EXPECT_DOUBLE_EQ(h.t, 3.0);
    EXPECT_EQ(h.normal.z, 1.0);
    // sqrt(0.36 + 0.16) = 0.72 > 0.5: outside.
    EXPECT_FALSE(disc.intersect({{1.6, 2.4, 5}, {0, 0, -1}}, 0, INFINITY, h));
    EXPECT_FALSE(disc.is_closed());
}

TEST(Disc, RespectsTheRayIntervalAndIgnoresParallelRays) {
    const Disc disc({0, 0, 0}, {0, 1, 0}, 1, {0, 0, -1});
    SurfaceHit h;
    EXPECT_FALSE(disc.intersect({{0, 2, 0}, {0, -1, 0}}, 0, 1.5, h));
    EXPECT_TRUE(disc.intersect({{0, 2, 0}, {0, -1, 0}}, 0, 2.5, h));
    EXPECT_FALSE(disc.intersect({{0, 0, 0}, {1, 0, 0}}, 0, INFINITY, h));
}

TEST(Disc, FrameFollowsUpAndNormal) {
    // Seen from the front (+z looking down -z), u runs right (+x) and v up (+y).
    const Disc disc({0, 0, 0}, {0, 0, 1}, 1, {0, 1, 0});
    EXPECT_NEAR(disc.frame().u.x, 1, 1e-15);
    EXPECT_NEAR(disc.frame().v.y, 1, 1e-15);
    EXPECT_NEAR(dot(cross(disc.frame().u, disc.frame().v), disc.normal()), 1, 1e-15);
}

TEST(Disc, BoundsAreTight) {
    // A tilted disc reaches r sqrt(1 - n_a^2) along each axis.
    const Vec3 n = normalize(Vec3{0, 1, 1});
    const Disc disc({0, 0, 0}, n, 2, {1, 0, 0});
    const Aabb b = disc.bounds();
    EXPECT_NEAR(b.hi.x, 2, 1e-12);
    EXPECT_NEAR(b.hi.y, 2 * std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(b.lo.z, -2 * std::sqrt(0.5), 1e-12);
    // Every hit lies inside the bounds.
    SurfaceHit h;
    for (double a = 0; a < 6.28; a += 0.1) {
        const Vec3 p = disc.frame().at(1.999 * std::cos(a), 1.999 * std::sin(a));
        ASSERT_TRUE(disc.intersect({p + n, -n}, 0, INFINITY, h));
        for (int k = 0; k < 3; ++k) {
            EXPECT_GE(h.point[k], b.lo[k] - 1e-12);
            EXPECT_LE(h.point[k], b.hi[k] + 1e-12);
        }
    }
}

}  // namespace
}  // namespace lenslab
