// Mirrors and coordinate breaks in lens files (Zemax GLAS MIRROR, CODE V REFL, Zemax COORDBRK
// folds and tilted elements): read into lens groups whose mirror elements turn the light back, the
// files' negative thicknesses becoming distances along the light's way, and written back to .zmx
// unchanged. The telescope is a Ritchey-Chretien typed from the textbook formulas (Schroeder,
// Astronomical Optics, 2nd ed., section 6.2): F 2000, mirrors D = 500 apart, focus B = 700 behind
// the secondary.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "analysis/report/analyze_request.h"
#include "lensfile/lens_file_text.h"
#include "lensfile/lens_group_from_prescription.h"
#include "lensfile/seq_reader.h"
#include "lensfile/zmx_reader.h"
#include "lensfile/zmx_writer.h"
#include "scene/lens_file_import.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

using json = nlohmann::json;

std::string data(const std::string& name) {
    return std::string(LENSLAB_SOURCE_DIR) + "/scenes/" + name;
}

double analysed_efl(const std::string& path) {
    const Scene scene = parse_scene(R"({"objects": [{"type": "lens_file", "file": ")" + path +
                                        R"(", "vertex": [0, 0, 0], "axis": [0, 0, 1]}]})",
                                    "test", "", {.require_camera = false});
    AnalyzeRequest request;
    request.report_keys = {"efl"};
    return analyze_report(scene, request)["efl"].get<double>();
}

TEST(LensFileMirrors, AZemaxTelescopesMirrorsBecomeMirrorElements) {
    const ImportedLens lens = import_lens_file(data("ritchey_chretien.zmx"), "rc");
    const json group = json(lens.group);
    ASSERT_EQ(group["elements"].size(), 2u);
    const json& primary = group["elements"][0];
    const json& secondary = group["elements"][1];
    EXPECT_EQ(primary["mirror"]["shape"], "conic");
    EXPECT_DOUBLE_EQ(primary["mirror"]["radius"].get<double>(), 1.0 / -0.00065);
    EXPECT_DOUBLE_EQ(primary["gap"].get<double>(), 500.0);  // DISZ -500: back along the axis
    EXPECT_DOUBLE_EQ(primary["diameter"].get<double>(), 250.0);
    EXPECT_DOUBLE_EQ(primary["hole_diameter"].get<double>(), 60.0);  // OBSC 0 30 on a mirror
    EXPECT_DOUBLE_EQ(secondary["mirror"]["k"].get<double>(), -7.015625);
    EXPECT_FALSE(secondary.contains("gap"));
    EXPECT_DOUBLE_EQ(lens.bench["image_distance"].get<double>(), 700.0);
    EXPECT_DOUBLE_EQ(lens.bench["stop_position"].get<double>(), 0.0);
    EXPECT_NEAR(analysed_efl(data("ritchey_chretien.zmx")), 2000.0, 1e-6);
}

// The lens file imported, exported as .zmx and imported again: the .zmx written, after
// checking that both imports are the same lens and system data.
std::string expect_zmx_round_trip(const std::string& file, const std::string& name) {
    const ImportedLens first = import_lens_file(file, name);
    const json scene = json(imported_scene_json(first, file));
    const std::string zmx =
        zmx_from_lens_object(scene["objects"][0], "objects[0]", json::object(), scene["bench"]);
    const auto out = std::filesystem::temp_directory_path() /
                     ("lenslab_mirror_round_trip_" + std::to_string(::getpid()) + ".zmx");
    std::ofstream(out) << zmx;
    const ImportedLens second = import_lens_file(out.string(), name);
    std::filesystem::remove(out);
    EXPECT_EQ(first.group, second.group) << zmx;
    EXPECT_EQ(first.bench, second.bench) << zmx;
    return zmx;
}

TEST(LensFileMirrors, ATelescopeRoundTripsThroughZemaxUnchanged) {
    const std::string zmx = expect_zmx_round_trip(data("ritchey_chretien.zmx"), "rc");
    EXPECT_NE(zmx.find("GLAS MIRROR"), std::string::npos);
    EXPECT_NE(zmx.find("DISZ -500"), std::string::npos);
}

ImportedLens seq_lens(const std::string& text) {
    const std::vector<std::string> lines = decode_lens_file_lines(text, "test.seq");
    return lens_group_from_prescription(read_seq(lines, "test.seq"), "test");
}

std::string seq_error(const std::string& text) {
    try {
        (void)seq_lens(text);
    } catch (const LensFileError& e) {
        return e.what();
    }
    return "";
}

// A lens behind a concave mirror, met on the way back: its thickness and the gaps negative in
// the file, its faces signed along the axis.
TEST(LensFileMirrors, ALensAfterAMirrorIsCrossedOnTheWayBack) {
    const ImportedLens lens = seq_lens(
        "EPD 20\nS -200 -60 REFL\n  CIR 15\nS -40 -4 N-BK7_SCHOTT\n  CIR 8\nS 40 -30\n  CIR 8\n"
        "SI 0 0\n");
    const json group = json(lens.group);
    ASSERT_EQ(group["elements"].size(), 2u);
    EXPECT_DOUBLE_EQ(group["elements"][0]["gap"].get<double>(), 60.0);
    EXPECT_DOUBLE_EQ(group["elements"][1]["thickness"].get<double>(), 4.0);
    EXPECT_DOUBLE_EQ(group["elements"][1]["front"]["radius"].get<double>(), -40.0);
    EXPECT_DOUBLE_EQ(lens.bench["image_distance"].get<double>(), -30.0);
}

TEST(LensFileMirrors, WhatALensGroupCannotHoldIsRefusedWithItsLine) {
    // A Mangin mirror: the mirror on the back of the glass.
    EXPECT_EQ(seq_error("EPD 20\nS -300 5 N-BK7_SCHOTT\n  CIR 15\nS -400 -5 REFL\n  CIR 15\n"
                        "S -300 -100\n  CIR 15\nSI 0 0\n")
                  .rfind("test.seq:4: surface 2: a mirror on a glass face (a Mangin mirror", 0),
              0u);
    // A positive thickness after one mirror puts the next surface behind the light.
    EXPECT_EQ(seq_error("EPD 20\nS -200 60 REFL\n  CIR 15\nS -40 -4 N-BK7_SCHOTT\n  CIR 8\n"
                        "S 40 -30\n  CIR 8\nSI 0 0\n")
                  .rfind("test.seq:2: an air space of 60 after surface 1 (light travels back "
                         "after a mirror: must be < 0)",
                         0),
              0u);
}

// Zemax writes a fold mirror as a coordinate break, the mirror and a coordinate break of the
// same tilt (a periscope from the open rayoptics-like test files: two flat mirrors at 45 and
// -45 degrees about x): read as tilted mirror elements, written back the same way.
TEST(LensFileMirrors, ZemaxFoldMirrorsRoundTripAsTiltedMirrors) {
    const std::string file =
        std::string(LENSLAB_SOURCE_DIR) + "/tests/lensfile/data/public/zx_ol_fold_simple.zmx";
    const ImportedLens first = import_lens_file(file, "periscope");
    const json group = json(first.group);
    ASSERT_EQ(group["elements"].size(), 2u);
    EXPECT_EQ(group["elements"][0]["tilt_x"], 45.0);
    EXPECT_EQ(group["elements"][0]["gap"], 50.0);
    EXPECT_EQ(group["elements"][1]["tilt_x"], -45.0);
    const std::string zmx = expect_zmx_round_trip(file, "periscope");
    EXPECT_NE(zmx.find("TYPE COORDBRK\n  PARM 3 45\n  DISZ 0"), std::string::npos) << zmx;
}

// CODE V writes a fold as a mirror tilted by ADE (or BDE) with BEN; a tilt without BEN, or on
// a lens, is refused at its line.
TEST(LensFileMirrors, CodeVBendsAreFoldMirrors) {
    const ImportedLens lens = import_lens_file(
        std::string(LENSLAB_SOURCE_DIR) + "/tests/lensfile/data/public/cv_folded_lenses.seq",
        "relay");
    const json group = json(lens.group);
    ASSERT_EQ(group["elements"].size(), 7u);
    EXPECT_EQ(group["elements"][0]["tilt_x"], 60.0);
    EXPECT_EQ(group["elements"][3]["tilt_x"], -60.0);
    EXPECT_EQ(group["elements"][6]["tilt_x"], -45.0);
    EXPECT_EQ(seq_error("EPD 2\nS 0 10\nS 0 -5 REFL\n  CIR 3\n  ADE 30\nSI 0 0\n"),
              "test.seq:5: ADE: a tilt; a lens group holds elements on one axis, folded only by "
              "a tilted mirror with BEN");
}

// Zemax writes a decentred and tilted element as a coordinate break of order 0 before it and
// its inverse (order 1) after it, the thicknesses between returning to the first break's plane
// (zx_sk_cooke_tilt.zmx, the flint of a Cooke triplet): read as the element's decentre and
// tilts, measured about the central chief ray, written back the same way.
TEST(LensFileMirrors, AZemaxTiltedElementRoundTripsAsADecentredTiltedElement) {
    const std::string file =
        std::string(LENSLAB_SOURCE_DIR) + "/tests/lensfile/data/public/zx_sk_cooke_tilt.zmx";
    const ImportedLens first = import_lens_file(file, "tilted");
    const json group = json(first.group);
    ASSERT_EQ(group["elements"].size(), 3u);
    const json& flint = group["elements"][1];
    // The first break's PARM 1-5 (lines 121-125).
    EXPECT_EQ(flint["decenter_x"], -0.062814902461408195);
    EXPECT_EQ(flint["decenter_y"], -0.058001069043036001);
    EXPECT_EQ(flint["tilt_x"], -0.027239972197479499);
    EXPECT_EQ(flint["tilt_y"], -0.072380002207503805);
    EXPECT_EQ(flint["tilt_z"], -0.000698957981352194);
    EXPECT_EQ(flint["thickness"], 1.0);
    EXPECT_EQ(flint["gap"], 4.75);  // the return break's 1, less the way back, and the dummy's
    EXPECT_FALSE(group["elements"][0].contains("tilt_x"));
    const std::string zmx = expect_zmx_round_trip(file, "tilted");
    EXPECT_NE(zmx.find("  PARM 5 0.000698957981352194\n  PARM 6 1\n  DISZ 5.75"), std::string::npos)
        << zmx;

    // Measured about the central chief ray; without the motions, the same lens on its axis.
    json scene = json(imported_scene_json(first, file));
    AnalyzeRequest request;
    request.report_keys = {"efl", "first_order_basis"};
    const auto measure = [&](const json& s) {
        return analyze_report(parse_scene(s.dump(), "test", "", {.require_camera = false}),
                              request);
    };
    const auto tilted = measure(scene);
    for (const char* key : {"decenter_x", "decenter_y", "tilt_x", "tilt_y", "tilt_z"})
        scene["objects"][0]["elements"][1].erase(key);
    const auto nominal = measure(scene);
    EXPECT_EQ(tilted["first_order_basis"], "parabasal");
    EXPECT_EQ(nominal["first_order_basis"], "paraxial");
    // Decentres of 0.06 and tilts of 0.07 degrees change the focal length at second order:
    // here by 6 parts in 1e5 (the flint's prism deviation, 0.06 / 20, squared, times the
    // triplet's sensitivity).
    EXPECT_NEAR(tilted["efl"].get<double>(), nominal["efl"].get<double>(),
                1e-4 * nominal["efl"].get<double>());
}

// Zemax's BICONICX and TOROIDAL become biconic and toroidal faces; each section focuses as
// its thick lens: y, R 50 and -200 (the toroid's y curve); x, R 80 and flat (a rotation
// radius of 0 sweeps the y curve straight along x).
TEST(LensFileMirrors, ZemaxBiconicAndToroidalFacesAreReadAndWritten) {
    const std::string file =
        std::string(LENSLAB_SOURCE_DIR) + "/tests/lensfile/data/anamorphic_singlet.zmx";
    const ImportedLens lens = import_lens_file(file, "anamorphic");
    const json element = json(lens.group)["elements"][0];
    EXPECT_EQ(element["front"], json::parse(R"({"shape": "biconic", "radius_x": 80.0,
        "radius_y": 50.0, "k_x": 0.0, "k_y": -0.5})"));
    EXPECT_EQ(element["back"], json::parse(R"({"shape": "toroidal", "radius": -200.0, "k": 0.0,
        "coefficients": [1e-07], "radius_of_rotation": 0.0})"));
    const std::string zmx = expect_zmx_round_trip(file, "anamorphic");
    EXPECT_NE(zmx.find("TYPE TOROIDAL"), std::string::npos) << zmx;

    const Scene scene = parse_scene(R"({"objects": [{"type": "lens_file", "file": ")" + file +
                                        R"(", "vertex": [0, 0, 0], "axis": [0, 0, 1]}]})",
                                    "test", "", {.require_camera = false});
    AnalyzeRequest request;
    request.report_keys = {"efl", "efl_x", "first_order_basis"};
    const json report = analyze_report(scene, request);
    const double n = 1.5, t = 5, r1 = 50, r2 = -200;
    const double efl_y = 1 / ((n - 1) * (1 / r1 - 1 / r2 + (n - 1) * t / (n * r1 * r2)));
    EXPECT_EQ(report["first_order_basis"], "parabasal");
    EXPECT_NEAR(report["efl"].get<double>(), efl_y, 1e-7 * efl_y);
    EXPECT_NEAR(report["efl_x"].get<double>(), 80 / (n - 1), 1e-7 * 160);
}

// Zemax's SZERNSAG and XPOLYNOM (their extra data: the number of terms, the normalisation
// radius, the terms) become zernike and xy_polynomial faces, here from centimetres: the
// paraxial power of Z4 = √3 (2ρ² − 1) and of x² + y² terms as a thick lens's, Z4's constant
// making the lens thicker.
TEST(LensFileMirrors, ZemaxZernikeAndXyPolynomialFacesAreReadAndWritten) {
    const std::string file =
        std::string(LENSLAB_SOURCE_DIR) + "/tests/lensfile/data/freeform_singlet.zmx";
    const ImportedLens lens = import_lens_file(file, "freeform");
    const json element = json(lens.group)["elements"][0];
    EXPECT_EQ(element["front"]["shape"], "zernike");
    EXPECT_DOUBLE_EQ(element["front"]["radius"].get<double>(), 50.0);
    EXPECT_DOUBLE_EQ(element["front"]["normalization_radius"].get<double>(), 10.0);
    EXPECT_DOUBLE_EQ(element["front"]["coefficients"][0].get<double>(), 1e-7);  // cm^-3 to mm^-3
    ASSERT_EQ(element["front"]["zernike"].size(), 4u);
    EXPECT_DOUBLE_EQ(element["front"]["zernike"][3].get<double>(), 0.01);
    EXPECT_EQ(element["back"]["shape"], "xy_polynomial");
    EXPECT_EQ(element["back"]["terms"], json::parse("[0.0, 0.0, 0.05, 0.0, 0.05]"));
    const std::string zmx = expect_zmx_round_trip(file, "freeform");
    EXPECT_NE(zmx.find("TYPE SZERNSAG"), std::string::npos) << zmx;
    EXPECT_NE(zmx.find("XDAT 2 10"), std::string::npos) << zmx;

    const Scene scene = parse_scene(R"({"objects": [{"type": "lens_file", "file": ")" + file +
                                        R"(", "vertex": [0, 0, 0], "axis": [0, 0, 1]}]})",
                                    "test", "", {.require_camera = false});
    AnalyzeRequest request;
    request.report_keys = {"efl", "efl_x"};
    const json report = analyze_report(scene, request);
    const double n = 1.5, z4 = 0.01, rn = 10;
    const double c1 = 1 / 50.0 + 4 * std::sqrt(3.0) * z4 / (rn * rn), t = 5 + std::sqrt(3.0) * z4;
    const double c2 = -1 / 40.0 + 2 * 0.05 / (rn * rn);
    const double efl = 1 / ((n - 1) * (c1 - c2 + (n - 1) * t * c1 * c2 / n));
    EXPECT_NEAR(report["efl"].get<double>(), efl, 1e-7 * efl);
    EXPECT_NEAR(report["efl_x"].get<double>(), efl, 1e-7 * efl);
}

// Other coordinate breaks are refused with their line: here the return break does not undo
// the first (its tilt differs).
TEST(LensFileMirrors, ACoordinateBreakThatNeitherFoldsNorMovesAnElementIsRefused) {
    const std::vector<std::string> lines = {"MODE SEQ",        "UNIT MM X W X CM MR CPMM",
                                            "ENPD 10",         "SURF 0",
                                            "  DISZ INFINITY", "SURF 1",
                                            "  TYPE COORDBRK", "  PARM 3 2",
                                            "  DISZ 0",        "SURF 2",
                                            "  CURV 0.02",     "  DISZ 4",
                                            "  GLAS N-BK7",    "  DIAM 10",
                                            "SURF 3",          "  CURV -0.02",
                                            "  DISZ -4",       "  DIAM 10",
                                            "SURF 4",          "  TYPE COORDBRK",
                                            "  PARM 3 -1",     "  PARM 6 1",
                                            "  DISZ 50",       "SURF 5",
                                            "  DISZ 0"};
    try {
        (void)lens_group_from_prescription(read_zmx(lines, "test.zmx"), "lens");
        FAIL() << "accepted";
    } catch (const LensFileError& e) {
        EXPECT_NE(std::string(e.what()).find("test.zmx:8: coordinate break with a tilt about x"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace lenslab
