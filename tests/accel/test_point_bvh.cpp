// The point hierarchy finds exactly the points whose discs a ray segment crosses: the same
// set, with the same projections, as testing every point.

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "accel/point_bvh.h"
#include "math/rng.h"

namespace lenslab {
namespace {

TEST(PointBvh, FindsWhatTestingEveryPointFinds) {
    Rng rng(7, 0);
    std::vector<Vec3> points(5000);
    std::vector<double> radii(points.size());
    for (size_t i = 0; i < points.size(); ++i) {
        points[i] = {rng.uniform() * 4 - 2, rng.uniform() * 4 - 2, rng.uniform() * 4 - 2};
        radii[i] = 0.01 + 0.2 * rng.uniform();
    }
    const PointBvh bvh(
        points.size(), [&](size_t i) { return points[i]; }, [&](size_t i) { return radii[i]; });
    for (int q = 0; q < 200; ++q) {
        const Vec3 o{rng.uniform() * 6 - 3, rng.uniform() * 6 - 3, rng.uniform() * 6 - 3};
        const Ray ray{
            o, normalize(Vec3{rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5})};
        const double t_max = q % 4 == 0 ? INFINITY : 4 * rng.uniform();
        std::vector<size_t> found, expected;
        bvh.for_each_near(ray, t_max, [&](size_t i, double t, double r2) {
            found.push_back(i);
            EXPECT_NEAR(t, dot(points[i] - o, ray.direction), 1e-12);
            EXPECT_DOUBLE_EQ(r2, radii[i] * radii[i]);
        });
        for (size_t i = 0; i < points.size(); ++i) {
            const Vec3 v = points[i] - o;
            const double t = dot(v, ray.direction);
            if (t >= 0 && t <= t_max && length_squared(v) - t * t <= radii[i] * radii[i])
                expected.push_back(i);
        }
        std::sort(found.begin(), found.end());
        EXPECT_EQ(found, expected) << "query " << q;
    }
}

TEST(PointBvh, EmptyFindsNothing) {
    const PointBvh bvh(
        0, [](size_t) { return Vec3{}; }, [](size_t) { return 1.0; });
    int n = 0;
    bvh.for_each_near(Ray{{0, 0, 0}, {0, 0, 1}}, INFINITY, [&](size_t, double, double) { ++n; });
    EXPECT_EQ(n, 0);
}

}  // namespace
}  // namespace lenslab
