// A zoom's configurations in a Zemax file (MNUM, THIC records of the multi-configuration
// editor): the file's own surfaces by default, with a warning that others exist; a chosen
// configuration's thicknesses; a configuration the file lacks refused.

#include <gtest/gtest.h>

#include "geometry/lens/lens_solid.h"
#include "lensfile/lens_file_error.h"
#include "scene/lens_file_import.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

const std::string kZoomFile = LENSLAB_TEST_DATA "/lensfile/data/cooke_configurations.zmx";

// The air gap after the first element, which configurations 1, 2 and 3 set to 12.93, 10.5
// and 15.25 (THIC 2).
double first_gap(const ImportedLens& lens) {
    return lens.group["elements"][0]["gap"].get<double>();
}

TEST(LensFileConfigurations, TheFilesOwnSurfacesAndAWarning) {
    const ImportedLens lens = import_lens_file(kZoomFile, "zoom");
    EXPECT_DOUBLE_EQ(first_gap(lens), 12.93);
    ASSERT_EQ(lens.warnings.size(), 1u);
    EXPECT_EQ(lens.warnings[0].message,
              "3 configurations (MNUM): the lens as configuration 1, the one its surfaces hold (a "
              "configuration number takes another)");
}

TEST(LensFileConfigurations, AChosenConfigurationsThicknesses) {
    EXPECT_DOUBLE_EQ(first_gap(import_lens_file(kZoomFile, "zoom", 1.0, 2)), 10.5);
    EXPECT_DOUBLE_EQ(first_gap(import_lens_file(kZoomFile, "zoom", 1.0, 3)), 15.25);
    // The rest of the lens as the file has it.
    const ImportedLens one = import_lens_file(kZoomFile, "zoom", 1.0, 1);
    const ImportedLens three = import_lens_file(kZoomFile, "zoom", 1.0, 3);
    EXPECT_EQ(one.group["elements"][1], three.group["elements"][1]);
    EXPECT_TRUE(three.warnings.empty());
}

TEST(LensFileConfigurations, AConfigurationTheFileLacksIsRefused) {
    try {
        (void)import_lens_file(kZoomFile, "zoom", 1.0, 4);
        FAIL() << "configuration 4 was read";
    } catch (const LensFileError& e) {
        EXPECT_NE(
            std::string(e.what()).find("configuration 4: the file has 3 (MNUM), numbered from 1"),
            std::string::npos)
            << e.what();
    }
}

// A scene's lens_file takes a configuration too.
TEST(LensFileConfigurations, ASceneLensFileTakesItsConfiguration) {
    const nlohmann::json scene = {{"objects",
                                   {{{"type", "lens_file"},
                                     {"file", kZoomFile},
                                     {"vertex", {0, 0, 0}},
                                     {"axis", {0, 0, 1}},
                                     {"configuration", 2}}}}};
    const Scene s = scene_from_json(scene, "", {.require_camera = false});
    ASSERT_GE(s.objects.size(), 2u);
    const LensPrescription* first = s.objects[0].shape->lens_prescription();
    const LensPrescription* second = s.objects[1].shape->lens_prescription();
    ASSERT_TRUE(first && second);
    const double back = first->centre.z + 0.5 * first->thickness;
    const double front = second->centre.z - 0.5 * second->thickness;
    EXPECT_NEAR(front - back, 10.5, 1e-9);
}

}  // namespace
}  // namespace lenslab
