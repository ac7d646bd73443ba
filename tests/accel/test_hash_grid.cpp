// The hash grid against brute force: every point within the radius is visited, once.

#include <gtest/gtest.h>

#include <set>
#include <vector>

#include "accel/hash_grid.h"
#include "math/rng.h"

namespace lenslab {
namespace {

std::vector<Vec3> random_points(size_t n, double spread, uint64_t seed) {
    Rng rng(seed, 0);
    std::vector<Vec3> p(n);
    for (Vec3& v : p)
        v = {rng.uniform() * spread, rng.uniform() * spread, rng.uniform() * spread * 0.1};
    return p;
}

TEST(HashGrid, FindsEveryPointWithinTheRadiusOnce) {
    const std::vector<Vec3> points = random_points(20000, 10.0, 1);
    const HashGrid grid(
        points.size(), [&](size_t i) { return points[i]; }, 0.3);
    ASSERT_EQ(grid.size(), points.size());
    Rng rng(2, 0);
    for (int q = 0; q < 300; ++q) {
        const Vec3 c{rng.uniform() * 11 - 0.5, rng.uniform() * 11 - 0.5, rng.uniform() * 1.2 - 0.1};
        const double r = 0.05 + rng.uniform() * 0.6;  // smaller and larger than a cell
        std::multiset<size_t> visited;
        grid.for_each_near(c, r, [&](size_t slot) { visited.insert(grid.item(slot)); });
        for (size_t i = 0; i < points.size(); ++i) {
            const bool inside = length_squared(points[i] - c) <= r * r;
            if (inside) {
                EXPECT_EQ(visited.count(i), 1u) << "query " << q << " point " << i;
            } else {
                EXPECT_LE(visited.count(i), 1u);
            }
        }
    }
}

TEST(HashGrid, ReorderPutsDataInSlotOrder) {
    const std::vector<Vec3> points = random_points(1000, 1.0, 3);
    const HashGrid grid(
        points.size(), [&](size_t i) { return points[i]; }, 0.1);
    std::vector<size_t> index(points.size());
    for (size_t i = 0; i < index.size(); ++i) index[i] = i;
    const std::vector<size_t> ordered = grid.reorder(index);
    std::set<size_t> all(ordered.begin(), ordered.end());
    EXPECT_EQ(all.size(), points.size());
    for (size_t s = 0; s < ordered.size(); ++s) EXPECT_EQ(ordered[s], grid.item(s));
}

TEST(HashGrid, HugeSpreadEnlargesTheCells) {
    // 2^21 cells per axis at most: points 1e7 apart with 1e-3 cells would need 1e10.
    const std::vector<Vec3> points{{0, 0, 0}, {1e7, 0, 0}, {1e7, 1e7, 1e7}, {0.5, 0, 0}};
    const HashGrid grid(
        points.size(), [&](size_t i) { return points[i]; }, 1e-3);
    EXPECT_GE(grid.cell_size(), 1e7 / (1 << 21));
    std::set<size_t> found;
    grid.for_each_near({1e7, 1e7, 1e7}, 1.0, [&](size_t slot) { found.insert(grid.item(slot)); });
    EXPECT_TRUE(found.count(2));
}

TEST(HashGrid, EmptyGridVisitsNothing) {
    const HashGrid grid(
        0, [](size_t) { return Vec3{}; }, 1.0);
    int visits = 0;
    grid.for_each_near({0, 0, 0}, 10.0, [&](size_t) { ++visits; });
    EXPECT_EQ(visits, 0);
}

}  // namespace
}  // namespace lenslab
