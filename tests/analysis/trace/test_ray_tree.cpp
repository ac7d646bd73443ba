#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "analysis/trace/ray_tree.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

const char* kGlassBallOverFloor = R"({
  "camera": {"position": [0, 5, 0], "look_at": [0, 0, 0], "up": [0, 0, 1]},
  "materials": {"glass": {"transparency": 1, "ior": 1.5}, "floor": {"color": 0.5}},
  "objects": [
    {"name": "ball", "type": "sphere", "center": [0, 2, 0], "radius": 1, "material": "glass"},
    {"name": "floor", "type": "triangle", "vertices": [[-10, 0, -10], [10, 0, -10], [0, 0, 10]],
     "material": "floor"}
  ]
})";

TEST(RayTree, NormalIncidenceSplitsFourAndNinetySixPercent) {
    const Scene scene = parse_scene(kGlassBallOverFloor);
    const RayTree tree = trace_ray_tree(scene, {{0, 5, 0}, {0, -1, 0}}, {});
    ASSERT_EQ(tree.root.children.size(), 2u);
    const RayTreeNode& reflected = tree.root.children[0];
    const RayTreeNode& refracted = tree.root.children[1];
    EXPECT_EQ(reflected.event, Event::Reflect);
    EXPECT_EQ(refracted.event, Event::Refract);
    EXPECT_NEAR(reflected.weight, 0.04, 1e-12);  // Fresnel R at normal incidence, n = 1.5
    EXPECT_NEAR(refracted.weight, 0.96, 1e-12);
    EXPECT_NEAR(refracted.to->y, 3.0, 1e-12);
    EXPECT_EQ(scene.objects[refracted.object].name, "ball");
    // The reflected ray goes back up and escapes.
    ASSERT_EQ(reflected.children.size(), 1u);
    EXPECT_EQ(reflected.children[0].event, Event::Escape);
    // Through the ball: 0.96 * 0.96 of the power reaches the floor and is absorbed there.
    const RayTreeNode* exit = nullptr;
    for (const auto& c : refracted.children)
        if (c.event == Event::Refract) exit = &c;
    ASSERT_NE(exit, nullptr);
    EXPECT_NEAR(exit->weight, 0.96 * 0.96, 1e-12);
    ASSERT_FALSE(exit->children.empty());
    EXPECT_EQ(exit->children[0].event, Event::Absorb);
    EXPECT_EQ(scene.objects[exit->children[0].object].name, "floor");
}

TEST(RayTree, PowerIsAccountedFor) {
    const Scene scene = parse_scene(kGlassBallOverFloor);
    for (double x : {0.0, 0.3, 0.7, 0.95}) {
        const RayTree tree = trace_ray_tree(scene, {{x, 5, 0.1}, {0, -1, 0}}, {16, 1e-9});
        EXPECT_NEAR(tree.escaped + tree.absorbed + tree.truncated, 1.0, 1e-9);
        EXPECT_LT(tree.truncated, 1e-6);
    }
}

TEST(RayTree, TotalInternalReflectionInsideGlass) {
    // A ray inside the unit ball along the chord at distance sin(60 deg) from the centre
    // meets the surface at 60 degrees from the normal (> 41.8, the critical angle), and is
    // reflected entirely.
    const Scene scene = parse_scene(kGlassBallOverFloor);
    const Vec3 origin{0, 2 + std::sin(60.0 * std::numbers::pi / 180.0), 0};
    const RayTree tree = trace_ray_tree(scene, {origin, {1, 0, 0}}, {3, 1e-9});
    ASSERT_EQ(tree.root.children.size(), 1u);
    EXPECT_EQ(tree.root.children[0].event, Event::Tir);
    EXPECT_NEAR(tree.root.children[0].weight, 1.0, 1e-12);
}

TEST(RayTree, MaxDepthTruncates) {
    const Scene scene = parse_scene(kGlassBallOverFloor);
    // max_depth 0: the first hit is recorded, no bounce after it is followed.
    const RayTree tree = trace_ray_tree(scene, {{0, 5, 0}, {0, -1, 0}}, {0, 1e-9});
    ASSERT_EQ(tree.root.children.size(), 2u);
    EXPECT_TRUE(tree.root.children[1].truncated);
    EXPECT_NEAR(tree.truncated, 1.0, 1e-12);
}

TEST(RayTree, JsonHasTheDocumentedFields) {
    const Scene scene = parse_scene(kGlassBallOverFloor);
    const auto j = to_json(scene, trace_ray_tree(scene, {{0, 5, 0}, {0, -1, 0}}, {}));
    const auto& first = j["tree"]["children"][0];
    for (const char* key : {"from", "to", "object", "event", "weight", "direction", "children"}) {
        EXPECT_TRUE(first.contains(key)) << key;
    }
    EXPECT_EQ(first["object"], "ball");
    EXPECT_EQ(j["tree"]["event"], "start");
    EXPECT_FALSE(j["tree"].contains("incidence_deg"));  // the start met no surface
}

// The angles at each surface: scenes/prism.json's beam through an equilateral prism of
// n = 1.5 at minimum deviation (Hecht, Optics, 5.5.1) meets the first face at
// asin(1.5 sin 30°) = 48.59° and refracts to 30°, then leaves the second face symmetrically.
TEST(RayTree, JsonGivesTheAnglesAndIndicesAtEachSurface) {
    const Scene scene = load_scene_file(LENSLAB_SOURCE_DIR "/scenes/prism.json");
    const auto j =
        to_json(scene, trace_ray_tree(scene, {{-2.6196, 0, -0.797}, {0.9478, 0, 0.3188}}, {}));
    const double incidence = std::asin(0.75) * 180 / std::numbers::pi;
    const auto refracted = [](const nlohmann::ordered_json& node) {
        for (const auto& c : node["children"]) {
            if (c["event"] == "refract") return c;
        }
        return nlohmann::ordered_json{};
    };
    const auto in = refracted(j["tree"]);
    EXPECT_NEAR(in["incidence_deg"].get<double>(), incidence, 0.01);
    EXPECT_NEAR(in["leaving_deg"].get<double>(), 30, 0.01);
    EXPECT_EQ(in["n_inside"], 1.5);
    EXPECT_EQ(in["n_outside"], 1.0);
    const auto out = refracted(in);
    EXPECT_NEAR(out["incidence_deg"].get<double>(), 30, 0.01);
    EXPECT_NEAR(out["leaving_deg"].get<double>(), incidence, 0.01);
    EXPECT_EQ(out["normal"].size(), 3u);
}

}  // namespace
}  // namespace lenslab
