// A lens surface standing alone as a mirror (geometry/lens/mirror_surface.h):
// - a paraboloid z = r^2 / (2R) (a conic of radius R, k = -1) reflects every ray parallel to
//   its axis through its focus at R/2 (Hecht, Optics, 5th ed., section 5.4.3): exactly, at
//   every height;
// - a central hole lets the rays inside it through, and the surface beyond is met again;
// - the mirror sits where its vertex and axis put it, and faces along its axis.

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/lens/conic_surface.h"
#include "geometry/lens/flat_surface.h"
#include "geometry/lens/mirror_surface.h"
#include "optics/refraction.h"

namespace lenslab {
namespace {

MirrorSurface paraboloid(const Vec3& vertex, const Vec3& axis, double hole = 0) {
    MirrorPrescription p;
    p.vertex = vertex;
    p.axis = axis;
    p.surface = std::make_shared<ConicSurface>(200.0, -1.0);
    p.diameter = 100.0;
    p.hole_diameter = hole;
    return MirrorSurface(p);
}

TEST(MirrorSurface, AParaboloidReflectsParallelRaysThroughItsFocus) {
    // Tilted and moved: the focus lies at vertex + axis R/2.
    const Vec3 vertex{3, -2, 7}, axis = normalize(Vec3{0.2, 0.1, 1.0});
    const MirrorSurface m = paraboloid(vertex, axis);
    const Vec3 focus = vertex + axis * 100.0;
    const Frame f = m.frame();
    for (const double r : {1.0, 10.0, 30.0, 49.0}) {
        for (const double phi : {0.0, 1.0, 2.5}) {
            const Vec3 start = vertex + f.to_world({r * std::cos(phi), r * std::sin(phi), 500.0});
            const Ray ray{start, -axis};
            SurfaceHit hit;
            ASSERT_TRUE(m.intersect(ray, 0.0, INFINITY, hit)) << r;
            // The normal faces the arriving light's side (+axis) at the vertex.
            EXPECT_GT(dot(hit.normal, axis), 0.0);
            const Vec3 out = reflect(ray.direction, hit.normal);
            // Distance of the focus from the reflected ray's line.
            const Vec3 to_focus = focus - hit.point;
            const double miss = length(to_focus - out * dot(to_focus, out));
            EXPECT_LT(miss, 1e-9) << "r " << r << " phi " << phi;
            EXPECT_GT(dot(to_focus, out), 0.0);  // towards it, not away
        }
    }
    // Outside the diameter, nothing.
    SurfaceHit hit;
    const Vec3 wide = vertex + f.to_world({51.0, 0.0, 500.0});
    EXPECT_FALSE(m.intersect({wide, -axis}, 0.0, INFINITY, hit));
}

TEST(MirrorSurface, AHoleLetsItsRaysThrough) {
    const MirrorSurface m = paraboloid({0, 0, 0}, {0, 0, 1}, 20.0);
    SurfaceHit hit;
    EXPECT_FALSE(m.intersect({{5, 0, 500}, {0, 0, -1}}, 0.0, INFINITY, hit));
    EXPECT_TRUE(m.intersect({{15, 0, 500}, {0, 0, -1}}, 0.0, INFINITY, hit));
    EXPECT_NEAR(hit.point.z, 15.0 * 15.0 / 400.0, 1e-12);
    // A ray rising at slope 0.05 in the x-z plane crosses z = x^2/400 at x = -5 (in the hole)
    // and at x = 5 + 400 * 0.05 = 25: it passes the hole and meets the surface there.
    const Vec3 d = normalize(Vec3{1.0, 0.0, 0.05});
    const Vec3 start{-30.0, 0.0, 0.0625 - 0.05 * 25.0};
    ASSERT_TRUE(m.intersect({start, d}, 0.0, INFINITY, hit));
    EXPECT_NEAR(hit.point.x, 25.0, 1e-9);
}

TEST(MirrorSurface, BoundsHoldTheSurface) {
    const MirrorSurface m = paraboloid({1, 2, 3}, normalize(Vec3{1, 1, 0}));
    const Aabb b = m.bounds();
    for (double x = -50; x <= 50; x += 10) {
        for (double y = -50; y <= 50; y += 10) {
            if (x * x + y * y > 2500) continue;
            const Vec3 p = m.point_at(x, y);
            for (int k = 0; k < 3; ++k) {
                EXPECT_GE(p[k], b.lo[k] - 1e-9);
                EXPECT_LE(p[k], b.hi[k] + 1e-9);
            }
        }
    }
}

}  // namespace
}  // namespace lenslab
