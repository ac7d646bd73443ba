#include <gtest/gtest.h>

#include <cmath>

#include "geometry/triangle.h"

namespace lenslab {
namespace {

TEST(Triangle, HitInsideAndMissOutside) {
    const Triangle tri({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    SurfaceHit h;
    ASSERT_TRUE(tri.intersect({{0.25, 0.25, 2}, {0, 0, -1}}, 0, INFINITY, h));
    EXPECT_DOUBLE_EQ(h.t, 2.0);
    EXPECT_NEAR(h.point.x, 0.25, 1e-15);
    EXPECT_NEAR(h.normal.z, 1.0, 1e-15);  // right-hand rule on the vertex order
    EXPECT_FALSE(tri.intersect({{0.6, 0.6, 2}, {0, 0, -1}}, 0, INFINITY, h));
    EXPECT_FALSE(tri.intersect({{-0.1, 0.5, 2}, {0, 0, -1}}, 0, INFINITY, h));
}

TEST(Triangle, IsTwoSidedAndIgnoresParallelRays) {
    const Triangle tri({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    SurfaceHit h;
    ASSERT_TRUE(tri.intersect({{0.2, 0.2, -1}, {0, 0, 1}}, 0, INFINITY, h));
    EXPECT_DOUBLE_EQ(h.t, 1.0);
    EXPECT_FALSE(tri.intersect({{0.2, 0.2, 1}, {1, 0, 0}}, 0, INFINITY, h));
}

TEST(Triangle, BoundsEncloseTheVertices) {
    const Triangle tri({0, -1, 2}, {3, 0, 0}, {1, 4, -1});
    const Aabb b = tri.bounds();
    EXPECT_EQ(b.lo.x, 0);
    EXPECT_EQ(b.lo.y, -1);
    EXPECT_EQ(b.lo.z, -1);
    EXPECT_EQ(b.hi.x, 3);
    EXPECT_EQ(b.hi.y, 4);
    EXPECT_EQ(b.hi.z, 2);
}

}  // namespace
}  // namespace lenslab
