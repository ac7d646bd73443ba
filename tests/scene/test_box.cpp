// The `box` object: a closed 12-triangle mesh read through its declaration (box_json.h),
// and a glass slab checked against the closed form of a plane-parallel plate.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "analysis/trace/ray_tree.h"
#include "geometry/triangle_mesh.h"
#include "scene/scene_json.h"
#include "util/scene_error.h"

namespace lenslab {
namespace {

using nlohmann::json;

json scene_with(const json& object) {
    return {{"camera", {{"position", {0, 0, 5}}, {"look_at", {0, 0, 0}}}},
            {"materials", {{"glass", {{"transparency", 1}, {"ior", 1.5}}}}},
            {"objects", json::array({object})}};
}

json slab(double thickness) {
    return {{"type", "box"},
            {"name", "slab"},
            {"center", {0, 0, 0}},
            {"size", {20, 20, thickness}},
            {"material", "glass"}};
}

std::string error_of(const json& object) {
    try {
        (void)scene_from_json(scene_with(object));
        return "";
    } catch (const SceneError& e) {
        return e.what();
    }
}

TEST(Box, IsAClosedMeshOfTwelveTriangles) {
    const Scene scene = scene_from_json(scene_with(
        {{"type", "box"}, {"center", {1, 2, 3}}, {"size", {2, 4, 6}}, {"material", "glass"}}));
    ASSERT_EQ(scene.objects.size(), 1u);
    const SceneObject& o = scene.objects[0];
    EXPECT_EQ(o.type, ObjectType::Mesh);
    EXPECT_EQ(o.name, "objects[0]");
    const auto* mesh = dynamic_cast<const TriangleMesh*>(o.shape.get());
    ASSERT_NE(mesh, nullptr);
    EXPECT_EQ(mesh->triangle_count(), 12u);
    EXPECT_TRUE(mesh->is_closed());
    const Aabb b = mesh->bounds();
    EXPECT_NEAR(b.lo.x, 0, 1e-12);
    EXPECT_NEAR(b.hi.x, 2, 1e-12);
    EXPECT_NEAR(b.lo.y, 0, 1e-12);
    EXPECT_NEAR(b.hi.y, 4, 1e-12);
    EXPECT_NEAR(b.lo.z, 0, 1e-12);
    EXPECT_NEAR(b.hi.z, 6, 1e-12);
}

TEST(Box, OrientedByUpAndFacing) {
    // x edges along up × facing = [0, 1, 0] × [1, 0, 0] = [0, 0, -1].
    const Scene scene = scene_from_json(scene_with({{"type", "box"},
                                                    {"center", {0, 0, 0}},
                                                    {"size", {2, 4, 6}},
                                                    {"facing", {1, 0, 0}},
                                                    {"material", "glass"}}));
    const Aabb b = scene.objects[0].shape->bounds();
    EXPECT_NEAR(b.hi.x, 3, 1e-12);
    EXPECT_NEAR(b.hi.y, 2, 1e-12);
    EXPECT_NEAR(b.hi.z, 1, 1e-12);
}

TEST(Box, RefusesASizeNotAboveZeroWithItsPath) {
    json o = slab(1);
    o["size"] = {1, 2, 0};
    EXPECT_EQ(error_of(o), "objects[0].size[2]: must be > 0, got 0");
    o["size"] = {-1, 2, 3};
    EXPECT_EQ(error_of(o), "objects[0].size[0]: must be > 0, got -1");
    o["size"] = {1, 2};
    EXPECT_EQ(error_of(o), "objects[0].size: must be [x, y, z] (full edge lengths)");
    o.erase("size");
    EXPECT_EQ(error_of(o), "objects[0].size: missing (required)");
}

TEST(Box, RefusesABadFrameDetectorAndEmission) {
    json o = slab(1);
    o["facing"] = {0, 1, 1};
    EXPECT_EQ(error_of(o),
              "objects[0].facing: must be perpendicular to up (the angle between them is 45 "
              "degrees)");
    o = slab(1);
    o["up"] = {0, 0, 1};
    EXPECT_EQ(error_of(o),
              "objects[0].facing: the default facing [0, 0, 1] is not perpendicular to up; give "
              "facing");
    o = slab(1);
    o["detector"] = true;
    EXPECT_EQ(error_of(o),
              "objects[0].detector: only a triangle, disc or rectangle can be a detector (this is "
              "a box)");
    o = slab(1);
    o["material"] = {{"emission", {{"intensity", 1}}}};
    EXPECT_EQ(error_of(o),
              "objects[0].material: only spheres can emit light (the material has an emission)");
    o = slab(1);
    o["radius"] = 1;
    EXPECT_NE(error_of(o).find("objects[0].radius"), std::string::npos) << error_of(o);
}

TEST(Box, UnknownTypeSuggestsBox) {
    json o = slab(1);
    o["type"] = "bx";
    EXPECT_EQ(error_of(o),
              "objects[0].type: unknown object type 'bx' (known: sphere, triangle, disc, "
              "rectangle, lens, lens_group, mesh, prism, implicit, box, mirror, lens_file; did you "
              "mean 'box'?)");
}

// A plane-parallel plate of thickness t and index n (in air) leaves a ray parallel to itself,
// displaced sideways by t sin(θ) (1 − cos(θ) / sqrt(n² − sin²(θ))) (Hecht, Optics, §5.2).
double traced_displacement(double thickness, double theta, Vec3& exit_direction) {
    const Scene scene = scene_from_json(scene_with(slab(thickness)));
    const Vec3 d{std::sin(theta), 0, -std::cos(theta)};
    // Aimed at the middle of the front face, so it leaves through the back face at any angle.
    const Vec3 origin = Vec3{0, 0, 0.5 * thickness} - d * 2.0;
    const RayTree tree = trace_ray_tree(scene, {origin, d}, {});
    // root -> refract (in) -> refract (out)
    const RayTreeNode* in = nullptr;
    for (const auto& c : tree.root.children) {
        if (c.event == Event::Refract) in = &c;
    }
    EXPECT_NE(in, nullptr);
    if (!in) return NAN;
    const RayTreeNode* out = nullptr;
    for (const auto& c : in->children) {
        if (c.event == Event::Refract) out = &c;
    }
    EXPECT_NE(out, nullptr);
    if (!out) return NAN;
    exit_direction = out->direction;
    // The distance from the exit point (where the ray refracts out) to the incoming line.
    return out->to ? length(cross(*out->to - origin, d)) : NAN;
}

TEST(Box, GlassSlabAtNormalIncidenceLeavesTheRayUndeviated) {
    Vec3 dir;
    const double shift = traced_displacement(0.5, 0.0, dir);
    EXPECT_NEAR(shift, 0.0, 1e-12);
    EXPECT_NEAR(dir.x, 0.0, 1e-12);
    EXPECT_NEAR(dir.y, 0.0, 1e-12);
    EXPECT_NEAR(dir.z, -1.0, 1e-12);
}

TEST(Box, GlassSlabDisplacesAnObliqueRayByThePlateFormula) {
    const double n = 1.5, t = 0.5;
    for (double degrees : {10.0, 30.0, 45.0, 60.0, 80.0}) {
        const double theta = degrees * std::numbers::pi / 180.0;
        Vec3 dir;
        const double shift = traced_displacement(t, theta, dir);
        const double s = std::sin(theta), c = std::cos(theta);
        const double expected = t * s * (1.0 - c / std::sqrt(n * n - s * s));
        EXPECT_NEAR(shift, expected, 1e-9 * expected) << degrees << " degrees";
        // And parallel to the incoming ray.
        EXPECT_NEAR(dir.x, s, 1e-12) << degrees << " degrees";
        EXPECT_NEAR(dir.z, -c, 1e-12) << degrees << " degrees";
    }
}

}  // namespace
}  // namespace lenslab
