// Media bounded by closed shapes: the `medium` key (closed shapes only), the surfaceless
// boundary of a shape with a medium and no material (light and shadow rays pass straight
// through it), and which medium each segment of a ray crosses when media nest (a glass lens
// inside a smoke box, a box in fog).

#include <gtest/gtest.h>

#include <string>

#include "scene/scene_json.h"
#include "scene/segment_medium.h"
#include "util/scene_error.h"

namespace lenslab {
namespace {

// A smoke box 4 units wide about the origin holding a clear glass lens at its centre (its
// vertices at z = -0.25 and 0.25), with `atmosphere` (JSON, or empty) around it.
Scene smoke_box_with_lens(const std::string& atmosphere, const std::string& lens_medium = "") {
    return parse_scene(R"({
      "camera": {"position": [0, 0, -10], "look_at": [0, 0, 0]},
      )" + (atmosphere.empty() ? "" : "\"atmosphere\": " + atmosphere + ",") +
                       R"(
      "objects": [
        {"type": "box", "name": "smoke", "center": [0, 0, 0], "size": [4, 4, 4],
         "medium": {"scattering": 0.5}},
        {"type": "lens", "name": "lens", "center": [0, 0, 0], "axis": [0, 0, 1],
         "thickness": 0.5, "diameter": 1, "front": {"shape": "sphere", "radius": 1.5},
         "back": {"shape": "sphere", "radius": -1.5},
         )" + (lens_medium.empty() ? "" : "\"medium\": " + lens_medium + ",") +
                       R"(
         "material": {"transparency": 1, "ior": 1.5}}]
    })");
}

// The medium of the segment from `origin` along `direction` to the next surface.
const Medium* medium_ahead(const Scene& scene, const Vec3& origin, const Vec3& direction) {
    Interaction it;
    const Ray ray{origin, direction};
    const bool hit = next_interaction(scene, ray, 550, it);
    return segment_medium(scene, ray, hit ? &it : nullptr);
}

TEST(SegmentMedium, NestedLensInSmokeBox) {
    const Scene scene = smoke_box_with_lens("");
    const Medium* smoke = &*scene.objects[0].medium;
    const Vec3 z{0, 0, 1};
    EXPECT_EQ(medium_ahead(scene, {0, 0, -10}, z), nullptr);  // clear air up to the box
    EXPECT_EQ(medium_ahead(scene, {0, 0, -1}, z), smoke);     // in the box, to the lens's front
    EXPECT_EQ(medium_ahead(scene, {0, 0, 0}, z), nullptr);    // inside the clear glass
    EXPECT_EQ(medium_ahead(scene, {0, 0, 1}, z), smoke);      // behind the lens, to the box's back
    EXPECT_EQ(medium_ahead(scene, {1.5, 0, -1}, z), smoke);   // past the lens's rim
    EXPECT_EQ(medium_ahead(scene, {0, 0, 10}, z), nullptr);   // leaving the scene
    EXPECT_EQ(medium_at(scene, {0, 0, -1}), smoke);
    EXPECT_EQ(medium_at(scene, {0, 0, -3}), nullptr);
}

TEST(SegmentMedium, AtmosphereOutsideTheBoxOnly) {
    const Scene scene = smoke_box_with_lens(R"({"scattering": 0.01})");
    const Medium* smoke = &*scene.objects[0].medium;
    const Medium* fog = &*scene.atmosphere;
    const Vec3 z{0, 0, 1};
    EXPECT_EQ(medium_ahead(scene, {0, 0, -10}, z), fog);
    EXPECT_EQ(medium_ahead(scene, {0, 0, -1}, z), smoke);
    EXPECT_EQ(medium_ahead(scene, {0, 0, 0}, z), nullptr);
    EXPECT_EQ(medium_ahead(scene, {0, 0, 10}, z), fog);
    EXPECT_EQ(medium_ahead(scene, {0, 10, 0}, {1, 0, 0}), fog);  // a miss
    EXPECT_EQ(medium_at(scene, {0, 0, -3}), fog);
}

TEST(SegmentMedium, MilkyGlassInsideSmokeIsTheInnermost) {
    const Scene scene = smoke_box_with_lens("", R"({"absorption": 0.2})");
    const Medium* smoke = &*scene.objects[0].medium;
    const Medium* milk = &*scene.objects[1].medium;
    EXPECT_EQ(medium_ahead(scene, {0, 0, 0}, {0, 0, 1}), milk);
    EXPECT_EQ(medium_ahead(scene, {0, 0, -1}, {0, 0, 1}), smoke);
    EXPECT_EQ(medium_at(scene, {0, 0, 0}), milk);
}

// A clear medium makes a pocket of clear air in the fog: inside it, no medium.
TEST(SegmentMedium, ClearPocketInTheAtmosphere) {
    const Scene scene = parse_scene(R"({
      "camera": {"position": [0, 0, -10], "look_at": [0, 0, 0]},
      "atmosphere": {"scattering": 0.1},
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "medium": {}}]
    })");
    EXPECT_EQ(medium_ahead(scene, {0, 0, 0}, {0, 0, 1}), nullptr);
    EXPECT_EQ(medium_at(scene, {0, 0.5, 0}), nullptr);
    EXPECT_EQ(medium_ahead(scene, {0, 0, -5}, {0, 0, 1}), &*scene.atmosphere);
}

TEST(SurfacelessBoundary, PassesLightAndShadowsStraightThrough) {
    const Scene scene = smoke_box_with_lens("");
    const Vec3 d = normalize(Vec3{0.3, 0.2, 1});
    Interaction it;
    ASSERT_TRUE(next_interaction(scene, {{-1.2, -0.8, -4}, d}, 480, it));
    EXPECT_EQ(it.object, &scene.objects[0]);
    ASSERT_EQ(it.scattering.count, 1);
    EXPECT_EQ(it.scattering.branches[0].event, Event::Refract);
    EXPECT_EQ(it.scattering.branches[0].weight, 1.0);
    const Vec3& out = it.scattering.branches[0].direction;
    EXPECT_EQ(out.x, d.x);
    EXPECT_EQ(out.y, d.y);
    EXPECT_EQ(out.z, d.z);
    EXPECT_EQ(it.scattering.diffuse, 0.0);
    EXPECT_FALSE(it.scattering.dispersive);
    // A shadow ray crosses the box's walls, not the lens.
    EXPECT_FALSE(scene.occluded({{1.5, 0, -10}, {0, 0, 1}}, 1e-9, 20));
    EXPECT_TRUE(scene.occluded({{0, 0, -10}, {0, 0, 1}}, 1e-9, 20));
}

// A tank of milky water: a real material refracts as before and holds the medium inside.
TEST(SurfacelessBoundary, AMaterialKeepsItsSurface) {
    const Scene scene = parse_scene(R"({
      "camera": {"position": [0, 0, -10], "look_at": [0, 0, 0]},
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
                   "medium": {"scattering": [0.02, 0.03, 0.05]},
                   "material": {"transparency": 1, "ior": 1.33}}]
    })");
    Interaction it;
    ASSERT_TRUE(next_interaction(scene, {{0.3, 0, -5}, {0, 0, 1}}, 550, it));
    EXPECT_EQ(it.scattering.count, 2);  // Fresnel reflection and refraction
    EXPECT_TRUE(scene.occluded({{0, 0, -5}, {0, 0, 1}}, 1e-9, 10));
    EXPECT_EQ(medium_ahead(scene, {0, 0, 0}, {0, 0, 1}), &*scene.objects[0].medium);
}

// A glass ball in a tank of milky water: the ball refracts against the water around it (the
// tank is the solid beyond its surface, as for cemented glass): at normal incidence it
// reflects ((1.5 - 1.33) / (1.5 + 1.33))^2, not air's 4%; the water around it is milky.
TEST(SurfacelessBoundary, GlassInAWaterTankRefractsAgainstTheWater) {
    const Scene scene = parse_scene(R"({
      "camera": {"position": [0, 0, -10], "look_at": [0, 0, 0]},
      "objects": [
        {"type": "box", "center": [0, 0, 0], "size": [4, 4, 4],
         "medium": {"scattering": 0.2}, "material": {"transparency": 1, "ior": 1.33}},
        {"type": "sphere", "center": [0, 0, 0], "radius": 0.5,
         "material": {"transparency": 1, "ior": 1.5}}]
    })");
    Interaction it;
    const Ray ray{{0, 0, -1}, {0, 0, 1}};
    ASSERT_TRUE(next_interaction(scene, ray, 550, it));
    EXPECT_EQ(it.object, &scene.objects[1]);
    double reflected = 0;
    for (int i = 0; i < it.scattering.count; ++i) {
        if (it.scattering.branches[i].event == Event::Reflect)
            reflected += it.scattering.branches[i].weight;
    }
    const double r = (1.5 - 1.33) / (1.5 + 1.33);
    EXPECT_NEAR(reflected, r * r, 1e-9);
    EXPECT_EQ(segment_medium(scene, ray, &it), &*scene.objects[0].medium);
}

std::string medium_error_of(const std::string& object) {
    try {
        (void)parse_scene(R"({"camera": {"position": [0, 0, -10], "look_at": [0, 0, 0]},
                              "objects": [)" +
                          object + "]}");
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

TEST(ShapeMedium, OpenShapesAreRefused) {
    EXPECT_EQ(medium_error_of(R"({"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]],
                           "medium": {"scattering": 1}})"),
              "objects[0].medium: a medium fills a solid: this triangle is an open surface");
    EXPECT_EQ(medium_error_of(R"({"type": "disc", "center": [0, 0, 0], "normal": [0, 0, 1],
                           "radius": 1, "medium": {"scattering": 1},
                           "material": {"color": 0.5}})"),
              "objects[0].medium: a medium fills a solid: this disc is an open surface");
    EXPECT_EQ(medium_error_of(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1,
                           "medium": {"g": 2}})"),
              "objects[0].medium.g: must be between -1 and 1, got 2");
    // Without a medium, the material is still required.
    EXPECT_EQ(medium_error_of(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1})"),
              "objects[0].material: missing (required)");
}

}  // namespace
}  // namespace lenslab
