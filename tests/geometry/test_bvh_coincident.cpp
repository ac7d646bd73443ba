// Primitives whose centres coincide leave the SAH no plane to split at; the build must still
// bound every leaf (issue 15: five million copies of one triangle made one leaf).

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "accel/bvh_stats.h"
#include "geometry/bvh.h"
#include "geometry/sphere.h"
#include "geometry/triangle_mesh.h"

namespace lenslab {
namespace {

constexpr int kCoincidentCopies = 10000;

TEST(BvhCoincident, IdenticalBoxesMakeSmallLeaves) {
    const std::vector<Aabb> boxes(kCoincidentCopies, Aabb{{0, 0, 0}, {1, 1, 1}});
    const BvhLayout layout = build_bvh(boxes, 4);
    const BvhStats stats = bvh_stats(layout);
    EXPECT_LE(stats.max_leaf_size, 4);
    EXPECT_GE(stats.leaves, static_cast<size_t>(kCoincidentCopies / 4));
    EXPECT_EQ(stats.nodes, 2 * stats.leaves - 1);
    // Every primitive is in exactly one leaf.
    std::vector<int> seen(kCoincidentCopies, 0);
    for (int p : layout.order) ++seen[static_cast<size_t>(p)];
    for (int s : seen) ASSERT_EQ(s, 1);
}

TEST(BvhCoincident, OrdinarySpreadIsUnchanged) {
    // Distinct centres: the split never needs the index fallback, leaves stay as SAH makes
    // them (here at most 4 too).
    std::vector<Aabb> boxes;
    for (int i = 0; i < 1000; ++i) {
        const double x = i * 0.37;
        boxes.push_back(Aabb{{x, 0, 0}, {x + 0.1, 0.1, 0.1}});
    }
    EXPECT_LE(bvh_stats(build_bvh(boxes, 4)).max_leaf_size, 4);
}

TEST(BvhCoincident, ConcentricSpheresStillGiveTheNearestHit) {
    // Same centre, growing radii: the outermost is the nearest from outside.
    std::vector<std::unique_ptr<Sphere>> spheres;
    std::vector<const Shape*> shapes;
    for (int i = 0; i < 1000; ++i) {
        spheres.push_back(std::make_unique<Sphere>(Vec3{0, 0, 0}, 1.0 + 0.001 * i));
        shapes.push_back(spheres.back().get());
    }
    const Bvh bvh(shapes);
    BvhHit hit;
    ASSERT_TRUE(bvh.intersect(Ray{{0, 0, -10}, {0, 0, 1}}, 1e-9, INFINITY, hit));
    EXPECT_EQ(hit.primitive, 999);
    EXPECT_NEAR(hit.surface.t, 10.0 - 1.999, 1e-9);
}

// The mesh's BVH is build_bvh's (leaf size 4, bounded as above); its hits must stay right.
TEST(BvhCoincident, MeshOfIdenticalTrianglesIsHitAtTheRightDistance) {
    std::vector<Vec3> vertices{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    std::vector<MeshTriangle> triangles(kCoincidentCopies, MeshTriangle{0, 1, 2});
    const TriangleMesh pile(vertices, triangles, false);
    SurfaceHit hit;
    ASSERT_TRUE(pile.intersect(Ray{{0.25, 0.25, -2}, {0, 0, 1}}, 1e-9, INFINITY, hit));
    EXPECT_DOUBLE_EQ(hit.t, 2.0);

    // One copy moved nearer the ray's origin, in the middle of the pile: it is the hit.
    vertices.insert(vertices.end(), {{0, 0, -0.5}, {1, 0, -0.5}, {0, 1, -0.5}});
    triangles[kCoincidentCopies / 2] = {3, 4, 5};
    const TriangleMesh pile_and_one(vertices, triangles, false);
    ASSERT_TRUE(pile_and_one.intersect(Ray{{0.25, 0.25, -2}, {0, 0, 1}}, 1e-9, INFINITY, hit));
    EXPECT_DOUBLE_EQ(hit.t, 1.5);
    ASSERT_TRUE(pile_and_one.intersect(Ray{{0.25, 0.25, 2}, {0, 0, -1}}, 1e-9, INFINITY, hit));
    EXPECT_DOUBLE_EQ(hit.t, 2.0);
}

}  // namespace
}  // namespace lenslab
