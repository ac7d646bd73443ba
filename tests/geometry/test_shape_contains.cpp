// Inside tests, which decide the medium beyond a cemented surface: every closed shape agrees
// with its own closed-form definition of inside; open shapes contain nothing.

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/mesh_shapes.h"
#include "geometry/sphere.h"
#include "geometry/triangle.h"
#include "math/rng.h"

namespace lenslab {
namespace {

TEST(ShapeContains, SphereByDistanceToItsCentre) {
    const Sphere s({1, 2, 3}, 2);
    EXPECT_TRUE(s.contains({1, 2, 3}));
    EXPECT_TRUE(s.contains({2.9, 2, 3}));
    EXPECT_FALSE(s.contains({3.1, 2, 3}));
}

// The generic test (which way the first surface along a ray faces) on a closed mesh: a
// unit-side equilateral prism of height 1, checked against its three side planes and caps.
TEST(ShapeContains, ClosedMeshByTheFacingOfItsNearestSurface) {
    const MeshGeometry g = make_prism({});
    const TriangleMesh prism(g.vertices, g.triangles, true);
    const double d = std::cos(M_PI / 6), b = 0.5;  // apex to base, half the base
    auto inside = [&](const Vec3& p) {
        // Cross-section in (w, z) with w = cross(axis, facing) = x: apex at z = d/2, base
        // corners at z = -d/2, w = -/+ b.
        if (std::abs(p.y) > 0.5 || p.z < -0.5 * d) return false;
        const double half_width = b * (0.5 * d - p.z) / d;
        return std::abs(p.x) < half_width;
    };
    Rng rng(7, 1);
    int checked = 0;
    for (int i = 0; i < 4000; ++i) {
        const Vec3 p{rng.uniform() - 0.5, 1.2 * rng.uniform() - 0.6, rng.uniform() - 0.5};
        // Skip points within 1e-6 of the surface, where rounding may decide either way.
        const double margin = 1e-6;
        if (inside(p) != inside(p + Vec3{margin, 0, 0}) ||
            inside(p) != inside(p - Vec3{margin, 0, 0}) ||
            inside(p) != inside(p + Vec3{0, margin, margin}) ||
            inside(p) != inside(p - Vec3{0, margin, margin})) {
            continue;
        }
        EXPECT_EQ(prism.contains(p), inside(p)) << p.x << " " << p.y << " " << p.z;
        ++checked;
    }
    EXPECT_GT(checked, 3900);
}

TEST(ShapeContains, OpenSurfacesContainNothing) {
    const Triangle t({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    EXPECT_FALSE(t.contains({0.2, 0.2, 0}));
    EXPECT_FALSE(t.contains({0.2, 0.2, -1}));
}

}  // namespace
}  // namespace lenslab
