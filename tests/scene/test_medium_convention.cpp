// The scene's index convention ("ambient") and length unit ("length_unit_mm"): what each
// changes in the materials read from catalogue glasses, and the errors for bad values.

#include <gtest/gtest.h>

#include <string>

#include "optics/air_index.h"
#include "optics/glass_library.h"
#include "scene/scene_json.h"
#include "util/scene_error.h"

namespace lenslab {
namespace {

Scene medium_scene(const std::string& top_level) {
    std::string text = R"({"camera": {"position": [0, 0, -5], "look_at": [0, 0, 0]}, )";
    text.append(top_level);
    text.append(R"("materials": {"bk7": {"transparency": 1, "glass": "N-BK7"},
                                 "plain": {"transparency": 1, "ior": 1.5}}})");
    return parse_scene(text);
}

TEST(MediumConvention, AirIsTheDefaultAndLeavesCatalogueIndicesAsTheyAre) {
    const Scene scene = medium_scene("");
    const IndexModel& catalogue = *lookup_glass("N-BK7").glass->model;
    EXPECT_EQ(scene.materials[0].ior(kLineD), catalogue.n(kLineD));
    EXPECT_EQ(medium_scene(R"("ambient": "air",)").materials[0].ior(kLineD), catalogue.n(kLineD));
}

TEST(MediumConvention, VacuumMakesCatalogueIndicesAbsolute) {
    // Absolute index at the vacuum wavelength = the catalogue's (relative to air) at the air
    // wavelength, times the index of air: N-BK7's n_d 1.51680 becomes 1.51721.
    const Scene scene = medium_scene(R"("ambient": "vacuum",)");
    const IndexModel& catalogue = *lookup_glass("N-BK7").glass->model;
    const double vacuum_d = vacuum_wavelength(kLineD);
    EXPECT_NEAR(scene.materials[0].ior(vacuum_d), catalogue.n(kLineD) * standard_air_index(kLineD),
                1e-9);
    EXPECT_NEAR(scene.materials[0].ior(vacuum_d), 1.51721, 1e-5);
    // A number is taken as written: relative to the ambient medium, whatever it is.
    EXPECT_EQ(scene.materials[1].ior(kLineD), 1.5);
}

TEST(MediumConvention, AbsorptionFollowsTheLengthUnit) {
    // N-BK7 has k data: its absorption per scene unit is per millimetre times the unit.
    const Scene mm = medium_scene("");
    const Scene cm = medium_scene(R"("length_unit_mm": 10,)");
    ASSERT_TRUE(mm.materials[0].absorption);
    ASSERT_TRUE(cm.materials[0].absorption);
    EXPECT_NEAR(cm.materials[0].absorption->per_unit(400),
                10 * mm.materials[0].absorption->per_unit(400), 1e-15);
    // No k, no absorption: the renderer's per-hit test stays a null pointer.
    EXPECT_FALSE(mm.materials[1].absorption);
}

TEST(MediumConvention, BadValuesAreRefusedWithTheirKey) {
    try {
        medium_scene(R"("ambient": "water",)");
        FAIL() << "accepted ambient water";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.path(), "ambient");
        EXPECT_NE(std::string(e.reason()).find("known: air, vacuum"), std::string::npos)
            << e.reason();
    }
    try {
        medium_scene(R"("length_unit_mm": 0,)");
        FAIL() << "accepted a zero length unit";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.path(), "length_unit_mm");
    }
}

}  // namespace
}  // namespace lenslab
