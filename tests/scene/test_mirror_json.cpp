// The `mirror` object (scene/mirror_json.h, docs/scene-format.md "Mirror"): read, refused
// with the key at fault, and traced. scenes/paraboloid_mirror.json's paraboloid (vertex
// radius 2, k = -1, facing up from (-0.8, 0.2, 0)) sends a ray falling parallel to its axis
// through its focus, f = R/2 = 1 above the vertex (Hecht, Optics, 5th ed., section 5.4.3).

#include <gtest/gtest.h>

#include <cmath>

#include "analysis/trace/ray_tree.h"
#include "scene/scene_json.h"
#include "util/scene_error.h"

namespace lenslab {
namespace {

std::string mirror_error(const std::string& mirror) {
    try {
        (void)parse_scene(R"({"objects": [)" + mirror + "]}", "test", "",
                          {.require_camera = false});
    } catch (const SceneError& e) {
        return e.path() + ": " + e.reason();
    }
    return "loaded";
}

TEST(MirrorJson, BadMirrorsAreRefusedAtTheirKey) {
    const std::string ok =
        R"({"type": "mirror", "vertex": [0, 0, 0], "axis": [0, 0, 1], "diameter": 2, )"
        R"("material": {"specular": 1}, )";
    EXPECT_EQ(mirror_error(ok + R"("surface": {"shape": "sphere", "radius": 5}})"), "loaded");
    EXPECT_EQ(mirror_error(ok + R"("surface": {"shape": "flat"}, "hole_diameter": 2})"),
              "objects[0].hole_diameter: must be less than diameter (2), got 2");
    EXPECT_EQ(mirror_error(ok + R"("surface": {"shape": "sphere", "radius": 0.5}})"),
              "objects[0].surface: sphere R=0.5 cannot span the diameter 2 (its largest is 1)");
    EXPECT_EQ(
        mirror_error(ok + R"("surface": {"shape": "sag", "formula": "sqrt(0.25 - r^2) - 0.5"}})")
            .rfind("objects[0].surface: sag undefined at (x, y) = (", 0),
        0u);
    EXPECT_EQ(mirror_error(ok + R"("surface": {"shape": "flat"}, "detector": true})")
                  .rfind("objects[0].detector", 0),
              0u);
    EXPECT_EQ(mirror_error(R"({"type": "mirror", "vertex": [0, 0, 0], "axis": [0, 0, 1],
        "diameter": 2, "surface": {"shape": "flat"}})"),
              "objects[0].material: missing (required)");
}

TEST(MirrorJson, TheParaboloidOfTheExampleSceneReflectsThroughItsFocus) {
    const Scene scene =
        load_scene_file(std::string(LENSLAB_SOURCE_DIR) + "/scenes/paraboloid_mirror.json");
    const Vec3 focus{-0.8, 1.2, 0.0};
    for (const double x : {0.1, 0.3, 0.55}) {
        SCOPED_TRACE(x);
        // Down onto the paraboloid, in front of the card (z > 0).
        const Ray ray{{-0.8 + x, 1.5, 0.2}, {0, -1, 0}};
        const RayTree tree = trace_ray_tree(scene, ray, {});
        // Two branches: what the surface absorbs, and the reflection.
        ASSERT_EQ(tree.root.children.size(), 2u);
        const RayTreeNode& hit = tree.root.children[1];
        ASSERT_EQ(hit.event, Event::Reflect);
        EXPECT_EQ(tree.root.children[0].event, Event::Absorb);
        ASSERT_EQ(scene.objects[hit.object].name, "paraboloid");
        ASSERT_TRUE(hit.to.has_value());
        // The reflected ray's line passes through the focus.
        const Vec3 to_focus = focus - *hit.to;
        const Vec3 d = normalize(hit.direction);
        EXPECT_LT(length(to_focus - d * dot(to_focus, d)), 1e-9);
        EXPECT_NEAR(hit.weight, 0.9, 1e-12);  // the aluminium's specular share
    }
}

}  // namespace
}  // namespace lenslab
