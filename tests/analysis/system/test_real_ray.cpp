// The sequential real-ray trace: it agrees with the renderer's own ray tree (which finds
// surfaces by intersecting the whole scene and refracts with the same Snell's law), and it
// flags rays clipped by a lens edge and rays totally reflected inside the glass.

#include <gtest/gtest.h>

#include <cmath>

#include "../lens_scene_builder.h"
#include "analysis/system/real_ray.h"
#include "analysis/trace/ray_tree.h"

namespace lenslab {
namespace {

using test::lens_scene;
using test::LensSpec;
using test::sphere;

// The refracted branch through every face, as the scene's ray tree follows it.
const RayTreeNode* refracted_path_end(const RayTree& tree, int faces) {
    const RayTreeNode* node = &tree.root;
    for (int i = 0; i < faces && node; ++i) {
        const RayTreeNode* next = nullptr;
        for (const RayTreeNode& c : node->children) {
            if (c.event == Event::Refract) next = &c;
        }
        node = next;
    }
    return node;
}

TEST(RealRay, AgreesWithTheScenesRayTree) {
    // Two air-spaced lenses, one an even asphere, traced both ways at the F line.
    const LensSpec a{"a", 0, 5, 25, sphere(50), sphere(-80), test::glass("N-BK7")};
    const LensSpec b{"b",
                     8,
                     4,
                     25,
                     R"({"shape": "asphere", "radius": 40, "k": -1, "coefficients": [-2e-6]})",
                     sphere(0),
                     test::glass("N-SF11")};
    const Scene scene = lens_scene({a, b});
    const OpticalSystem system = build_optical_system(scene);
    RayTreeOptions options;
    options.wavelength_nm = kLineF;
    options.min_weight = 1e-6;
    for (double h : {0.5, 4.0, 9.0}) {
        SCOPED_TRACE(h);
        const RealRay r = trace_real_ray(system, {{0, h, -10}, {0, 0, 1}}, kLineF);
        ASSERT_EQ(r.fate, RayFate::Passed);
        ASSERT_EQ(r.points.size(), 5u);
        // The scene's axis is the system's (origin at the first vertex, z = 0 there).
        const RayTree tree = trace_ray_tree(scene, {{0, h, -10}, {0, 0, 1}}, options);
        const RayTreeNode* end = refracted_path_end(tree, 4);
        ASSERT_TRUE(end && end->to);
        const Vec3 world_exit = system.to_world(r.exit_point());
        EXPECT_NEAR(length(world_exit - *end->to), 0.0, 1e-9);
        EXPECT_NEAR(length(system.direction_to_world(r.direction) - end->direction), 0.0, 1e-12);
    }
}

TEST(RealRay, RaysOutsideTheLensAreClipped) {
    const LensSpec a{"a", 0, 5, 20, sphere(50), sphere(-50)};
    const OpticalSystem system = build_optical_system(lens_scene({a}));
    const RealRay r = trace_real_ray(system, {{0, 10.5, -5}, {0, 0, 1}}, kLineD);
    EXPECT_EQ(r.fate, RayFate::Missed);
    EXPECT_EQ(r.surface, 0);
}

TEST(RealRay, TotalInternalReflectionIsFlagged) {
    // Flat front, convex back R = -10 over a diameter of 19: a ray at height h meets the back
    // face at incidence asin(h / 10) inside glass of n = 1.5, beyond the critical angle
    // asin(1 / 1.5) = 41.8 degrees when h > 6.67.
    const LensSpec a{"a", 0, 12, 19, sphere(0), sphere(-10)};
    const OpticalSystem system = build_optical_system(lens_scene({a}));
    EXPECT_EQ(trace_real_ray(system, {{0, 6.6, -5}, {0, 0, 1}}, kLineD).fate, RayFate::Passed);
    const RealRay r = trace_real_ray(system, {{0, 6.7, -5}, {0, 0, 1}}, kLineD);
    EXPECT_EQ(r.fate, RayFate::Reflected);
    EXPECT_EQ(r.surface, 1);
}

}  // namespace
}  // namespace lenslab
