#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "geometry/bvh.h"
#include "geometry/sphere.h"
#include "math/rng.h"
#include "math/sampling.h"

namespace lenslab {
namespace {

TEST(Bvh, NearestHitMatchesBruteForce) {
    Rng rng(4, 0);
    std::vector<std::unique_ptr<Sphere>> spheres;
    std::vector<const Shape*> shapes;
    for (int i = 0; i < 500; ++i) {
        spheres.push_back(std::make_unique<Sphere>(
            Vec3{rng.uniform() * 10, rng.uniform() * 10, rng.uniform() * 10},
            0.05 + 0.3 * rng.uniform()));
        shapes.push_back(spheres.back().get());
    }
    const Bvh bvh(shapes);
    for (int q = 0; q < 2000; ++q) {
        const Ray ray{
            {rng.uniform() * 10, rng.uniform() * 10, -5},
            normalize(sample_uniform_sphere(rng.uniform(), rng.uniform()) + Vec3{0, 0, 1.5})};
        double best = INFINITY;
        int best_i = -1;
        for (size_t i = 0; i < shapes.size(); ++i) {
            SurfaceHit h;
            if (shapes[i]->intersect(ray, 1e-9, best, h)) {
                best = h.t;
                best_i = int(i);
            }
        }
        BvhHit hit;
        const bool found = bvh.intersect(ray, 1e-9, INFINITY, hit);
        ASSERT_EQ(found, best_i >= 0);
        if (found) {
            EXPECT_EQ(hit.primitive, best_i);
            EXPECT_DOUBLE_EQ(hit.surface.t, best);
        }
        EXPECT_EQ(bvh.occluded(ray, 1e-9, INFINITY), found);
    }
}

// Objects at scales 2^k make SAH build a chain as deep as the object count; the build must
// switch to median splits so traversal stays within its stack.
TEST(Bvh, GeometricChainOfScalesStaysShallow) {
    std::vector<std::unique_ptr<Sphere>> spheres;
    std::vector<const Shape*> shapes;
    for (int k = 0; k < 300; ++k) {
        spheres.push_back(
            std::make_unique<Sphere>(Vec3{std::ldexp(1.0, k), 0, 0}, 0.1 * std::ldexp(1.0, k)));
        shapes.push_back(spheres.back().get());
    }
    const Bvh bvh(shapes);
    BvhHit hit;
    ASSERT_TRUE(bvh.intersect({{0.5, 0, 0}, {1, 0, 0}}, 0, INFINITY, hit));
    EXPECT_EQ(hit.primitive, 0);
    EXPECT_NEAR(hit.surface.t, 0.4, 1e-12);
}

TEST(Bvh, NanRayHitsNothing) {
    const Sphere s({0, 0, 0}, 1);
    const Bvh bvh({&s});
    BvhHit hit;
    EXPECT_FALSE(bvh.intersect({{NAN, 0, -5}, {0, 0, 1}}, 0, INFINITY, hit));
    EXPECT_FALSE(bvh.intersect({{0, 0, -5}, {NAN, 0, 1}}, 0, INFINITY, hit));
}

}  // namespace
}  // namespace lenslab
