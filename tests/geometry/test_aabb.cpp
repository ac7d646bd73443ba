// The box's point test: its faces count as inside, an empty box holds nothing.

#include <gtest/gtest.h>

#include <cmath>

#include "math/aabb.h"

namespace lenslab {
namespace {

TEST(Aabb, ContainsItsInsideAndFacesButNothingBeyond) {
    const Aabb box{{-1, 0, 2}, {1, 3, 4}};
    EXPECT_TRUE(box.contains({0, 1, 3}));
    EXPECT_TRUE(box.contains({-1, 0, 2})) << "a corner";
    EXPECT_TRUE(box.contains({1, 3, 4})) << "the opposite corner";
    EXPECT_FALSE(box.contains({1.000001, 1, 3}));
    EXPECT_FALSE(box.contains({0, -1e-9, 3}));
    EXPECT_FALSE(box.contains({0, 1, 4.5}));
    EXPECT_FALSE(box.contains({std::nan(""), 1, 3})) << "not a point";
}

TEST(Aabb, AnEmptyBoxContainsNothing) {
    const Aabb empty;
    EXPECT_TRUE(empty.empty());
    EXPECT_FALSE(empty.contains({0, 0, 0}));
}

}  // namespace
}  // namespace lenslab
