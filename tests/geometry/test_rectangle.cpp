// A rectangle: an open flat surface of a given width (along u = up x normal) and height
// (along v).

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/rectangle.h"

namespace lenslab {
namespace {

TEST(Rectangle, HitInsideMissOutside) {
    // Facing +z with up +y: width along x, height along y.
    const Rectangle rect({0, 0, 0}, {0, 0, 1}, 4, 2, {0, 1, 0});
    SurfaceHit h;
    ASSERT_TRUE(rect.intersect({{1.9, 0.9, 1}, {0, 0, -1}}, 0, INFINITY, h));
    EXPECT_DOUBLE_EQ(h.t, 1.0);
    EXPECT_EQ(h.normal.z, 1.0);
    EXPECT_FALSE(rect.intersect({{2.1, 0, 1}, {0, 0, -1}}, 0, INFINITY, h));
    EXPECT_FALSE(rect.intersect({{0, 1.1, 1}, {0, 0, -1}}, 0, INFINITY, h));
    ASSERT_TRUE(rect.intersect({{-1.9, -0.9, -1}, {0, 0, 1}}, 0, INFINITY, h));  // from behind
    EXPECT_FALSE(rect.is_closed());
}

TEST(Rectangle, UpOrientsTheHeight) {
    // Up along x: the height (2) runs along x, the width (4) along up x normal = -y.
    const Rectangle rect({0, 0, 0}, {0, 0, 1}, 4, 2, {1, 0, 0});
    EXPECT_NEAR(rect.frame().u.y, -1, 1e-15);
    SurfaceHit h;
    EXPECT_TRUE(rect.intersect({{0.9, 1.9, 1}, {0, 0, -1}}, 0, INFINITY, h));
    EXPECT_FALSE(rect.intersect({{1.1, 0, 1}, {0, 0, -1}}, 0, INFINITY, h));
}

TEST(Rectangle, BoundsHoldTheCorners) {
    const Rectangle rect({1, 1, 1}, normalize(Vec3{1, 1, 0}), 2, 3, {0, 0, 1});
    const Aabb b = rect.bounds();
    EXPECT_NEAR(b.hi.z - b.lo.z, 3, 1e-12);
    EXPECT_NEAR(b.hi.x - b.lo.x, 2 * std::sqrt(0.5), 1e-12);
}

}  // namespace
}  // namespace lenslab
