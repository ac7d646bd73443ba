// Lens groups with mirror elements (scene/lens_group_json.h, docs/scene-format.md "Lens
// group"): where their objects stand in space, and what is refused with the key at fault.
// The Cassegrain is the one of the docs: the primary at the vertex, the secondary 500 back
// towards the light, a lens met after it crossed on the way back.

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/lens/lens_solid.h"
#include "geometry/lens/mirror_surface.h"
#include "scene/scene_json.h"
#include "util/scene_error.h"

namespace lenslab {
namespace {

const char* const kMirror = R"("material": {"color": 0, "specular": 1})";
const char* const kGlass = R"("material": {"transparency": 1, "ior": 1.5})";

Scene group(const std::string& elements) {
    return parse_scene(R"({"objects": [{"type": "lens_group", "vertex": [0, 0, 0],
        "axis": [0, 0, 1], "diameter": 40, "elements": [)" +
                           elements + "]}]}",
                       "test", "", {.require_camera = false});
}

std::string group_error(const std::string& elements) {
    try {
        (void)group(elements);
    } catch (const SceneError& e) {
        return e.path() + ": " + e.reason();
    }
    return "loaded";
}

TEST(LensGroupJson, MirrorsTurnTheLightBackAndTheElementsAfterLieTheOtherWay) {
    const Scene scene =
        group(std::string(R"({"mirror": {"shape": "sphere", "radius": -400},
        "gap": 150, "hole_diameter": 10, )") +
              kMirror + R"(}, {"front": {"shape": "sphere", "radius": -60},
        "back": {"shape": "flat"}, "thickness": 4, "gap": 20, "diameter": 20, )" +
              kGlass + R"(}, {"mirror": {"shape": "flat"}, "diameter": 20, )" + kMirror + "}");
    ASSERT_EQ(scene.objects.size(), 3u);
    EXPECT_EQ(scene.objects[0].type, ObjectType::Mirror);
    const auto& primary = dynamic_cast<const MirrorSurface&>(*scene.objects[0].shape);
    EXPECT_EQ(primary.prescription().vertex.z, 0.0);
    EXPECT_EQ(primary.prescription().hole_diameter, 10.0);
    // The lens: its face met first 150 back from the primary, its centre 2 further back; as a
    // solid along +z its front is the face at lower z, the element's flat back.
    const auto& lens = dynamic_cast<const LensSolid&>(*scene.objects[1].shape).prescription();
    EXPECT_NEAR(lens.centre.z, -152.0, 1e-12);
    EXPECT_EQ(lens.front->describe(), "flat");
    // The second mirror 20 past the lens's far face, at z = -174; light turns to +z again.
    const auto& fold = dynamic_cast<const MirrorSurface&>(*scene.objects[2].shape);
    EXPECT_NEAR(fold.prescription().vertex.z, -174.0, 1e-12);
    EXPECT_EQ(scene.objects[2].group_axis.z, 1.0);
}

TEST(LensGroupJson, ATiltedMirrorFoldsTheAxis) {
    const Scene scene = group(std::string(R"({"front": {"shape": "flat"},
        "back": {"shape": "flat"}, "thickness": 2, "gap": 10, )") +
                              kGlass + R"(}, {"mirror": {"shape": "flat"}, "tilt_x": 45,
        "gap": 30, )" + kMirror +
                              R"(}, {"front": {"shape": "flat"},
        "back": {"shape": "flat"}, "thickness": 3, )" +
                              kGlass + "}");
    const auto& fold = dynamic_cast<const MirrorSurface&>(*scene.objects[1].shape).prescription();
    // The normal turned 45 degrees from +z towards -y; the beam leaves along +y.
    EXPECT_NEAR(fold.axis.y, -std::sqrt(0.5), 1e-15);
    EXPECT_NEAR(fold.axis.z, std::sqrt(0.5), 1e-15);
    const auto& after = dynamic_cast<const LensSolid&>(*scene.objects[2].shape).prescription();
    EXPECT_NEAR(after.centre.y, 31.5, 1e-12);
    EXPECT_NEAR(after.centre.z, 12.0, 1e-12);
    EXPECT_NEAR(after.axis.y, -1.0, 1e-15);
}

TEST(LensGroupJson, BadMirrorElementsAreRefusedAtTheirKey) {
    const std::string lens =
        std::string(R"({"front": {"shape": "flat"}, "back": {"shape": "flat"}, "thickness": 2, )") +
        kGlass;
    const std::string mirror = std::string(R"({"mirror": {"shape": "flat"}, )") + kMirror;
    EXPECT_EQ(group_error(mirror + R"(, "hole_diameter": 40})"),
              "objects[0].elements[0].hole_diameter: must be less than the mirror's diameter "
              "(40), got 40");
    EXPECT_EQ(group_error(mirror + "}, " + lens + "}"),
              "objects[0].elements[0].gap: a mirror needs a gap to the next element (light "
              "cannot pass from a mirror straight into a glass)");
    EXPECT_EQ(group_error(mirror + R"(, "tilt_x": 10, "tilt_y": 10})"),
              "objects[0].elements[0].tilt_y: a mirror folds the axis about one of its axes: "
              "give tilt_x or tilt_y, not both");
    EXPECT_EQ(group_error(lens + "}, " + mirror + "}"),
              "objects[0].elements[0].back: an element before a mirror needs a gap to it (a mirror "
              "on a glass face is not yet supported)");
    EXPECT_EQ(group_error(std::string(R"({"mirror": {"shape": "sphere", "radius": -10}, )") +
                          kMirror + "}"),
              "objects[0].elements[0].mirror: sphere R=-10 cannot span the diameter 40 (its "
              "largest is 20)");
    EXPECT_EQ(
        group_error(
            std::string(R"x({"mirror": {"shape": "sag", "formula": "sqrt(100 - r^2) - 10"}, )x") +
            kMirror + "}")
            .rfind("objects[0].elements[0].mirror: sag undefined at (x, y) = (", 0),
        0u);
}

}  // namespace
}  // namespace lenslab
