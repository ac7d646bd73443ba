// An imported lens file's system data as the bench's defaults
// (analysis/system/lens_bench_defaults.h): what the request leaves open comes from the file; what
// the user asks for always wins. The lens file is Thorlabs' AC254-100-A.zmx (tests/lensfile/data):
// F, d and C with d primary (WAVM, PWAV 2), one field on the axis, an entrance pupil of 25.4 mm
// (ENPD) and the image surface 97.1 mm behind the last vertex (the last DISZ).

#include <gtest/gtest.h>

#include <algorithm>

#include "../lens_scene_builder.h"
#include "analysis/system/lens_bench_defaults.h"
#include "util/scene_error.h"

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

TEST(LensBenchDefaults, TheFilesRayAimingUnlessAsked) {
    LensBench b;
    b.ray_aiming = "paraxial";
    const LensBenchDefaults d = with_lens_bench_defaults({}, b);
    EXPECT_EQ(d.request.ray_aiming, RayAiming::Paraxial);
    EXPECT_EQ(d.taken, std::vector<std::string>{"ray_aiming"});
    AnalyzeRequest real;
    real.ray_aiming = RayAiming::Real;
    EXPECT_EQ(with_lens_bench_defaults(real, b).request.ray_aiming, RayAiming::Real);
    const nlohmann::ordered_json j = analyze_report(
        parse_scene(R"({"bench": {"ray_aiming": "paraxial"}, "objects": [{"type": "lens",
            "center": [0, 0, 2], "axis": [0, 0, 1], "thickness": 4, "diameter": 20,
            "front": {"shape": "sphere", "radius": 50}, "back": {"shape": "flat"},
            "material": {"transparency": 1, "ior": 1.5}}]})",
                    "test", "", {.require_camera = false}),
        {});
    EXPECT_EQ(j["first_order"]["ray_aiming"], "paraxial");
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
              nlohmann::ordered_json::array(
                  {"wavelengths", "fields", "epd", "stop", "ray_aiming", "image_distance"}));
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

Scene singlet_from_its_file(const std::string& file) {
    return parse_scene(R"({"objects": [{"name": "singlet", "type": "lens_file", "file": ")" +
                           std::string(LENSLAB_SOURCE_DIR) + "/tests/analysis/data/" + file +
                           R"(", "vertex": [0, 0, 0], "axis": [0, 0, 1]})" + "]}",
                       "test", "", {.require_camera = false});
}

// The entrance pupil of a stop at the back vertex of a singlet (front radius R, thickness t,
// index n, air in front) is that vertex's paraxial image through the front face:
// n / t - 1 / e = (n - 1) / R, so e = 1 / (n / t - (n - 1) / R) from the front vertex.
TEST(LensBenchDefaults, TheFilesStopIsUsedWithoutStop) {
    const nlohmann::ordered_json j =
        analyze_report(singlet_from_its_file("singlet_stop_back.zmx"), {});
    EXPECT_EQ(j["first_order"]["stop"]["surface"], 2);
    const double n = 1.5, t = 6.0, r = 50.0;
    EXPECT_NEAR(j["first_order"]["entrance_pupil"]["position"].get<double>(),
                1.0 / (n / t - (n - 1.0) / r), 1e-12);
    const auto& taken = j["lens_file_bench"]["taken"];
    EXPECT_NE(std::find(taken.begin(), taken.end(), "stop"), taken.end());
    // --stop wins, and says the file's stop was not taken.
    AnalyzeRequest first;
    first.stop = 1;
    const nlohmann::ordered_json asked =
        analyze_report(singlet_from_its_file("singlet_stop_back.zmx"), first);
    EXPECT_EQ(asked["first_order"]["stop"]["surface"], 1);
    EXPECT_EQ(asked["first_order"]["entrance_pupil"]["position"].get<double>(), 0.0);
    EXPECT_EQ(asked["lens_file_bench"]["not_taken"][0], "stop: --stop 1 given");
}

// A stop in air 5 mm before a landscape singlet (a surface of its own in the file, which the
// lens group cannot hold): the bench puts a stop there. With nothing before it, the entrance
// pupil is the stop itself; a stop moved away from the lens changes the coma.
TEST(LensBenchDefaults, AStopInAirBeforeTheLensIsPutInPlace) {
    const nlohmann::ordered_json j =
        analyze_report(singlet_from_its_file("singlet_stop_in_front.zmx"), {});
    EXPECT_EQ(j["first_order"]["stop"]["surface"], 1);
    EXPECT_EQ(j["first_order"]["stop"]["label"], "stop");
    EXPECT_NEAR(j["first_order"]["entrance_pupil"]["position"].get<double>(), -5.0, 1e-12);
    EXPECT_NEAR(j["first_order"]["entrance_pupil"]["diameter"].get<double>(), 8.0, 1e-12);
    EXPECT_EQ(j["surfaces"].size(), 3u);
    // The stop surface adds no Seidel term (flat, air on both sides).
    EXPECT_EQ(j["seidel"]["surfaces"][0]["S_I"].get<double>(), 0.0);
    AnalyzeRequest at_the_lens;
    at_the_lens.stop = 2;
    const nlohmann::ordered_json moved =
        analyze_report(singlet_from_its_file("singlet_stop_back.zmx"), at_the_lens);
    EXPECT_GT(std::abs(j["seidel"]["total"]["S_II"].get<double>() -
                       moved["seidel"]["total"]["S_II"].get<double>()),
              1e-4);
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
