// An imported lens file's system data as the bench's defaults (analysis/lens_bench_defaults.h):
// what the request leaves open comes from the file; what the user asks for always wins.
// The lens file is Thorlabs' AC254-100-A.zmx (tests/lensfile/data): F, d and C with d
// primary (WAVM, PWAV 2), one field on the axis, an entrance pupil of 25.4 mm (ENPD) and the
// image surface 97.1 mm behind the last vertex (the last DISZ).

#include <gtest/gtest.h>

#include "analysis/lens_bench_defaults.h"
#include "lens_scene_builder.h"
#include "scene/scene_error.h"

namespace lenslab {
namespace {

LensBench three_lines(double primary) {
    LensBench b;
    b.wavelengths = {656.2725, 486.1327, 587.5618};
    b.primary_wavelength = primary;
    return b;
}

TEST(LensBenchDefaults, ThePrimaryWavelengthGoesToTheMiddle) {
    const LensBenchDefaults d = with_lens_bench_defaults({}, three_lines(587.5618));
    EXPECT_EQ(d.request.wavelengths, (std::vector<double>{486.1327, 587.5618, 656.2725}));
    EXPECT_EQ(d.taken, std::vector<std::string>{"wavelengths"});
    // A primary at an end of the band still lands in the middle, where the bench looks.
    EXPECT_EQ(with_lens_bench_defaults({}, three_lines(486.1327)).request.wavelengths,
              (std::vector<double>{587.5618, 486.1327, 656.2725}));
    LensBench one;
    one.wavelengths = {632.8};
    EXPECT_EQ(with_lens_bench_defaults({}, one).request.wavelength_nm, 632.8);
}

TEST(LensBenchDefaults, WhatTheUserAsksForWins) {
    LensBench b = three_lines(587.5618);
    b.fields_y = {0, 5};
    b.aperture_type = "entrance_pupil_diameter";
    b.aperture = 25.4;
    AnalyzeRequest asked;
    asked.wavelength_nm = 550;
    asked.wavelength_given = true;
    asked.fields = {0, 2};
    asked.f_number = 8;
    const LensBenchDefaults d = with_lens_bench_defaults(asked, b);
    EXPECT_TRUE(d.taken.empty());
    EXPECT_TRUE(d.request.wavelengths.empty());
    EXPECT_EQ(d.request.wavelength_nm, 550);
    EXPECT_EQ(d.request.fields, (std::vector<double>{0, 2}));
    EXPECT_EQ(d.request.epd, 0);
    EXPECT_EQ(d.request.f_number, 8);
}

TEST(LensBenchDefaults, FieldsAreAnglesFromTheAxis) {
    LensBench b;
    b.fields_x = {0, 3, 0};
    b.fields_y = {0, 4, 5};  // (3, 4) and (0, 5) are the same distance from the axis
    const LensBenchDefaults d = with_lens_bench_defaults({}, b);
    EXPECT_EQ(d.request.fields, (std::vector<double>{0, 5}));
    b.field_type = "object_height";
    const LensBenchDefaults heights = with_lens_bench_defaults({}, b);
    EXPECT_TRUE(heights.request.fields.empty());
    ASSERT_EQ(heights.not_taken.size(), 1u);
    EXPECT_NE(heights.not_taken[0].find("object_height"), std::string::npos);
}

TEST(LensBenchDefaults, TheImageSurfaceIsForFiguresMeasuredOnIt) {
    LensBench b;
    b.image_distance = 97.1;
    EXPECT_FALSE(with_lens_bench_defaults({}, b).request.image_distance);
    AnalyzeRequest spots;
    spots.spots = true;
    EXPECT_EQ(with_lens_bench_defaults(spots, b).request.image_distance, 97.1);
}

Scene achromat_from_its_file(const std::string& extra = "") {
    return parse_scene(
        R"({"objects": [{"name": "achromat", "type": "lens_file", "file": ")" LENSLAB_SOURCE_DIR
        R"(/tests/lensfile/data/AC254-100-A.zmx", "vertex": [0, 0, 0],
                       "axis": [0, 0, 1]})" +
            extra + "]}",
        "test", "", {.require_camera = false});
}

TEST(LensBenchDefaults, AnalyzeOfALensFileMeasuresAsItsFileSays) {
    AnalyzeRequest request;
    request.spots = true;
    const nlohmann::ordered_json j = analyze_report(achromat_from_its_file(), request);
    EXPECT_EQ(j["lens_file_bench"]["taken"],
              nlohmann::ordered_json::array({"wavelengths", "fields", "epd", "image_distance"}));
    EXPECT_DOUBLE_EQ(j["first_order"]["entrance_pupil"]["diameter"].get<double>(), 25.4);
    EXPECT_DOUBLE_EQ(j["spots"]["image_position"].get<double>(), 97.1);
    EXPECT_EQ(j["spots"]["wavelengths_nm"],
              nlohmann::ordered_json::array({486.1327, 587.5618, 656.2725}));
    // --lens naming another lens: the file's data are not that lens's.
    request.lens = "other";
    const nlohmann::ordered_json other = analyze_report(
        achromat_from_its_file(R"(, {"type": "lens", "name": "other", "center": [0, 0, 300],
            "axis": [0, 0, 1], "thickness": 4, "diameter": 20,
            "front": {"shape": "sphere", "radius": 50}, "back": {"shape": "flat"},
            "material": {"transparency": 1, "ior": 1.5}})"),
        request);
    EXPECT_FALSE(other.contains("lens_file_bench"));
}

TEST(LensBenchDefaults, ABadBenchBlockIsRefusedWithItsPath) {
    try {
        (void)parse_scene(R"({"bench": {"wavelengths": [486.1, -5]}, "objects": []})", "test", "",
                          {.require_camera = false});
        FAIL() << "a negative wavelength was read";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.path(), "bench.wavelengths[1]");
    }
}

}  // namespace
}  // namespace lenslab
