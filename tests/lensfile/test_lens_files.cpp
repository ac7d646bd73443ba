// Lens files in and out: Zemax .zmx and CODE V .seq prescriptions imported as lens_groups,
// checked against their vendors' and a textbook's published figures, a lens typed by hand,
// and themselves after a round trip through an exported .zmx.
//
// Prescriptions in tests/lensfile/data, written from the published numbers:
//   AC254-100-A (UTF-16 .zmx, as Zemax writes it) and LA1509 (UTF-8 .zmx): Thorlabs'
//   product tables, https://www.thorlabs.com/newgrouppage9.cfm?objectgroup_id=120 (achromat:
//   N-BK7 / SF5, R1 = 62.8, R2 = -45.7, R3 = -128.2, tc = 4.0 and 2.5, f = 100.1) and
//   objectgroup_id=13685 (LA1509: N-BK7, R = 51.5, tc = 3.6, f = 100.0), 25.4 mm across.
//   Cooke triplet (.zmx, .seq and by hand): W. J. Smith, Modern Optical Engineering, 4th ed.,
//   chapter 6, p. 119: SK4 / SF2 / SK4, radii 37.40, -341.48, -42.65, 36.40, 204.52, -37.05,
//   clear semi-apertures 14.7, 10.8, 11.6, stop 10.3; EFL 101.181.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "analysis/system/optical_system.h"
#include "analysis/system/paraxial.h"
#include "lensfile/lens_file_text.h"
#include "lensfile/lens_group_from_prescription.h"
#include "lensfile/seq_reader.h"
#include "lensfile/zmx_reader.h"
#include "lensfile/zmx_writer.h"
#include "optics/glass.h"
#include "scene/lens_file_import.h"
#include "scene/scene_json.h"
#include "util/scene_error.h"

namespace lenslab {
namespace {

using nlohmann::json;

std::string lens_data(const std::string& name) {
    return std::string(LENSLAB_TEST_DATA) + "/lensfile/data/" + name;
}

// The EFL at the d line of an imported lens, through the scene reader and the bench.
double imported_efl(const ImportedLens& lens, const std::string& path) {
    const Scene scene =
        scene_from_json(json(imported_scene_json(lens, path)), "", {.require_camera = false});
    return paraxial_trace(build_optical_system(scene), kLineD).efl;
}

// A .zmx or .seq text read from memory (the error cases): its lens, or its one error.
ImportedLens lens_from_text(const std::string& text, const std::string& format) {
    const std::string file = "test." + format;
    const std::vector<std::string> lines = decode_lens_file_lines(text, file);
    const LensFilePrescription p = format == "zmx" ? read_zmx(lines, file) : read_seq(lines, file);
    return lens_group_from_prescription(p, "test");
}

std::string error_of(const std::string& text, const std::string& format = "zmx") {
    try {
        (void)lens_from_text(text, format);
    } catch (const LensFileError& e) {
        return e.what();
    }
    return "";
}

TEST(LensFiles, ThorlabsAchromatFromUtf16ZemaxGivesThePublishedEfl) {
    const std::string path = lens_data("AC254-100-A.zmx");
    const ImportedLens lens = import_lens_file(path, "AC254-100-A");
    ASSERT_EQ(lens.group["elements"].size(), 2u);
    EXPECT_FALSE(lens.group["elements"][0].contains("back"));  // cemented
    EXPECT_EQ(lens.group["elements"][1]["material"]["glass"], "SCHOTT:SF5");
    const double efl = imported_efl(lens, path);
    std::printf("AC254-100-A imported: EFL %.4f mm (Thorlabs 100.1)\n", efl);
    EXPECT_NEAR(efl, 100.1, 0.005 * 100.1);
    EXPECT_TRUE(lens.warnings.empty()) << lens_file_warnings_text(lens, path);
}

TEST(LensFiles, ThorlabsPlanoConvexFromUtf8ZemaxGivesThePublishedEfl) {
    const std::string path = lens_data("LA1509.zmx");
    const ImportedLens lens = import_lens_file(path, "LA1509");
    const double efl = imported_efl(lens, path);
    std::printf("LA1509 imported: EFL %.4f mm (Thorlabs 100.0)\n", efl);
    EXPECT_NEAR(efl, 100.0, 0.005 * 100.0);
    EXPECT_EQ(lens.bench["aperture"], 25.4);
    EXPECT_EQ(lens.bench["primary_wavelength"], 587.5618);
    EXPECT_EQ(lens.bench["wavelengths"].size(), 3u);  // FTYP says 3 of the 4 WAVM are used
}

// Every radius, thickness, gap, diameter and glass of `got` against the hand-typed `want`.
void expect_same_group(const json& got, const json& want) {
    ASSERT_EQ(got["elements"].size(), want["elements"].size());
    for (size_t i = 0; i < want["elements"].size(); ++i) {
        SCOPED_TRACE("element " + std::to_string(i));
        const json& g = got["elements"][i];
        const json& w = want["elements"][i];
        for (const char* face : {"front", "back"}) {
            EXPECT_EQ(g[face]["shape"], w[face]["shape"]) << face;
            EXPECT_DOUBLE_EQ(g[face]["radius"].get<double>(), w[face]["radius"].get<double>())
                << face;
        }
        for (const char* key : {"thickness", "diameter"}) {
            EXPECT_DOUBLE_EQ(g[key].get<double>(), w[key].get<double>()) << key;
        }
        EXPECT_DOUBLE_EQ(g.value("gap", 0.0), w.value("gap", 0.0));
        EXPECT_EQ(g["material"]["glass"], w["material"]["glass"]);
    }
}

TEST(LensFiles, CookeTripletFromZemaxAndCodeVIsTheLensTypedByHand) {
    std::ifstream in(lens_data("cooke_triplet.json"));
    const json hand = json::parse(in)["objects"][0];
    const ImportedLens zmx = import_lens_file(lens_data("cooke_triplet.zmx"), "triplet");
    const ImportedLens seq = import_lens_file(lens_data("cooke_triplet.seq"), "triplet");
    {
        SCOPED_TRACE(".zmx");
        expect_same_group(json(zmx.group), hand);
    }
    {
        SCOPED_TRACE(".seq");
        expect_same_group(json(seq.group), hand);
    }
    // The stop, in the air space, is kept with the system data; both files agree on it.
    EXPECT_DOUBLE_EQ(zmx.bench["stop_position"].get<double>(), 5.90 + 12.93 + 2.50 + 2.00);
    EXPECT_DOUBLE_EQ(seq.bench["stop_position"].get<double>(), 5.90 + 12.93 + 2.50 + 2.00);
    EXPECT_EQ(zmx.bench["stop_semi_diameter"], 10.3);
    EXPECT_EQ(seq.bench["fields_y"], nlohmann::ordered_json({0, 7, 11.86}));
    EXPECT_EQ(zmx.bench["fields_y"], nlohmann::ordered_json({0, 7, 11.86}));
    // Smith's EFL from the catalogue glasses' n_d, within 0.5%.
    const double efl = imported_efl(seq, "cooke_triplet.seq");
    std::printf("Cooke triplet imported: EFL %.4f mm (Smith 101.181)\n", efl);
    EXPECT_NEAR(efl, 101.181, 0.005 * 101.181);
}

// .zmx -> lenslab -> .zmx -> lenslab: every number of the lens and its system data the same.
void expect_round_trip(const std::string& name) {
    SCOPED_TRACE(name);
    const ImportedLens first = import_lens_file(lens_data(name), "lens");
    const json scene = json(imported_scene_json(first, name));
    const std::string zmx =
        zmx_from_lens_object(scene["objects"][0], "objects[0]", json::object(), scene["bench"]);
    const auto out = std::filesystem::temp_directory_path() /
                     ("lenslab_round_trip_" + std::to_string(::getpid()) + ".zmx");
    std::ofstream(out) << zmx;
    const ImportedLens second = import_lens_file(out.string(), "lens");
    std::filesystem::remove(out);
    EXPECT_EQ(first.group, second.group) << zmx;
    EXPECT_EQ(first.bench, second.bench) << zmx;
}

TEST(LensFiles, ZemaxRoundTripLeavesEveryNumberUnchanged) {
    expect_round_trip("AC254-100-A.zmx");
    expect_round_trip("cooke_triplet.zmx");
    expect_round_trip("asphere_inches.zmx");
}

TEST(LensFiles, InchesAndEvenAsphereTermsAreConvertedToMillimetres) {
    const ImportedLens lens = import_lens_file(lens_data("asphere_inches.zmx"), "asphere");
    const json& front = lens.group["elements"][0]["front"];
    EXPECT_EQ(front["shape"], "asphere");
    EXPECT_DOUBLE_EQ(front["radius"].get<double>(), 25.4 / 0.8);
    EXPECT_EQ(front["k"], -0.6);
    // Zemax PARM 2, 3, 5 are the r^4, r^6, r^10 terms; a term of r^(2m) scales as in^(1-2m).
    ASSERT_EQ(front["coefficients"].size(), 4u);
    EXPECT_DOUBLE_EQ(front["coefficients"][0].get<double>(), -0.0123 / std::pow(25.4, 3));
    EXPECT_DOUBLE_EQ(front["coefficients"][1].get<double>(), 0.00045 / std::pow(25.4, 5));
    EXPECT_EQ(front["coefficients"][2], 0.0);
    EXPECT_DOUBLE_EQ(front["coefficients"][3].get<double>(), -1.5e-6 / std::pow(25.4, 9));
    EXPECT_DOUBLE_EQ(lens.group["elements"][0]["thickness"].get<double>(), 0.2 * 25.4);
    EXPECT_EQ(lens.group["elements"][0]["material"]["glass"], "OHARA:S-LAH64");
}

TEST(LensFiles, ALensFileInASceneIsPlacedAndAnalysedLikeItsLensGroup) {
    const Scene scene = load_scene_file(lens_data("triplet_scene.json"), {.require_camera = false});
    ASSERT_EQ(scene.objects.size(), 3u);
    EXPECT_EQ(scene.objects[0].group, "triplet");
    const OpticalSystem system = build_optical_system(scene);
    EXPECT_DOUBLE_EQ(system.origin.z, 10.0);
    const ImportedLens lens = import_lens_file(lens_data("cooke_triplet.zmx"), "triplet");
    EXPECT_DOUBLE_EQ(paraxial_trace(system, kLineD).efl, imported_efl(lens, "cooke_triplet.zmx"));

    const json missing = {{"objects",
                           {{{"type", "lens_file"},
                             {"file", "nowhere.zmx"},
                             {"vertex", {0, 0, 0}},
                             {"axis", {0, 0, 1}}}}}};
    try {
        (void)scene_from_json(missing, "", {.require_camera = false});
        ADD_FAILURE() << "a missing lens file was accepted";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.path(), "objects[0].file");
        EXPECT_EQ(e.reason(), "nowhere.zmx: no such file");
    }
}

// The AC254-100-A prescription in UTF-8, the base of the error cases below.
std::string achromat_text() {
    return "UNIT MM\nGCAT SCHOTT\nSURF 0\n  DISZ INFINITY\nSURF 1\n  TYPE STANDARD\n"
           "  CURV 0.015923566878980892\n  DISZ 4\n  GLAS N-BK7\n  DIAM 12.7\n"  // lines 5-10
           "SURF 2\n  CURV -0.021881838074398249\n  DISZ 2.5\n  GLAS SF5\n  DIAM 12.7\n"  // 11-15
           "SURF 3\n  CURV -0.0078003120124804995\n  DISZ 97\n  DIAM 12.7\n"              // 16-19
           "SURF 4\n  CURV 0\n  DISZ 0\n";                                                // 20-22
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    text.replace(text.find(from), from.size(), to);
    return text;
}

TEST(LensFiles, EncodingsAreDecodedAndBadBytesRefusedWithTheirLine) {
    const std::string text = "SURF 0\r\nCURV 0\r\n";
    std::string le = "\xFF\xFE", be = "\xFE\xFF";
    for (const char c : text) {
        le += c, le += '\0';
        be += '\0', be += c;
    }
    const std::vector<std::string> lines = {"SURF 0", "CURV 0"};
    EXPECT_EQ(decode_lens_file_lines(le, "f"), lines);
    EXPECT_EQ(decode_lens_file_lines(be, "f"), lines);
    EXPECT_EQ(decode_lens_file_lines("\xEF\xBB\xBF" + text, "f"), lines);
    const auto error = [](const std::string& bytes) {
        try {
            (void)decode_lens_file_lines(bytes, "f.zmx");
        } catch (const LensFileError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    // A lone UTF-16 surrogate on line 2; a binary file; UTF-16 cut in the middle of a unit.
    EXPECT_EQ(error(le.substr(0, 18) + std::string("\x00\xDC", 2) + le.substr(18)),
              "f.zmx:2: invalid UTF-16: a low surrogate on its own");
    EXPECT_EQ(error(std::string("SURF 0\nCURV \x93\xFF\x01", 15)),
              "f.zmx:2: not UTF-8 text: the byte 0x93 cannot start a character (a binary file, or "
              "another encoding)");
    EXPECT_EQ(error(le.substr(0, le.size() - 1)),
              "f.zmx: UTF-16 text with an odd number of bytes: the file is cut short");
}

TEST(LensFiles, BadFilesAreRefusedWithOneMessageNamingTheLine) {
    ASSERT_EQ(error_of(achromat_text()), "");
    // Truncated: the file stops inside the flint.
    EXPECT_EQ(error_of(achromat_text().substr(0, achromat_text().find("SURF 3"))),
              "test.zmx:14: the last surface has glass after it: the file is cut short (no image "
              "surface)");
    EXPECT_EQ(error_of(replaced(achromat_text(), "DISZ 97", "DISZ 9.7E")),
              "test.zmx:18: DISZ thickness: '9.7E' is not a number (the line may be cut short)");
    EXPECT_EQ(error_of(replaced(achromat_text(), "SURF 2\n", "SURF 2\n  TYPE GRID_SAG\n")),
              "test.zmx:12: surface type 'GRID_SAG' cannot be represented (lenslab reads "
              "STANDARD, EVENASPH, BICONICX, TOROIDAL, SZERNSAG, XPOLYNOM and COORDBRK)");
    EXPECT_EQ(error_of(replaced(achromat_text(), "GLAS N-BK7", "GLAS N-BK77")),
              "test.zmx:9: unknown glass 'N-BK77'; did you mean N-BK7 (SCHOTT)?");
    // R = 11 cannot reach the 12.7 mm semi-diameter.
    EXPECT_EQ(error_of(replaced(achromat_text(), "CURV 0.015923566878980892", "CURV 0.0909090909")),
              "test.zmx:7: surface 1: radius 11 mm is undefined beyond 11 mm from the axis, "
              "inside its element's semi-diameter 12.7 mm");
    EXPECT_EQ(error_of(replaced(achromat_text(), "GLAS SF5", "GLAS MIRROR")),
              "test.zmx:14: surface 2: a mirror on a glass face (a Mangin mirror, light reflected "
              "inside the glass) is not yet supported");
    EXPECT_EQ(
        error_of(replaced(achromat_text(), "SURF 3\n", "SURF 3\n  TYPE COORDBRK\n  PARM 3 5\n")),
        "test.zmx:18: coordinate break with a tilt about x: lenslab reads a fold (a mirror "
        "between two breaks of the same tilt about x or y) and a moved element (a break of "
        "order 0, the element, back to that plane, the inverse break of order 1)");
    const std::string seq = error_of(
        "S 50 5 N-BK7\n  CIR 10\nS -50 40\n  CIR 10\nS 20 3 NOSUCHGLASS_SCHOTT\n  CIR 1\n"
        "S 0 1\n  CIR 1\nSI 0 0\n",
        "seq");
    EXPECT_EQ(seq.rfind("test.seq:5: unknown glass 'NOSUCHGLASS'", 0), 0u) << seq;
}

TEST(LensFiles, LinesNotUnderstoodAreWarningsWithTheirLine) {
    const ImportedLens lens =
        lens_from_text(replaced(achromat_text(), "SURF 2\n", "SURF 2\n  FANCY 1 2 3\n"), "zmx");
    ASSERT_EQ(lens.warnings.size(), 1u);
    EXPECT_EQ(lens.warnings[0].line, 12);
    EXPECT_EQ(lens.warnings[0].message, "'FANCY' not understood; the line is left out");
    // CODE V: curvatures after RDM N, NBK7_SCHOTT without its hyphen.
    const ImportedLens seq = lens_from_text(
        "RDM N\nS 0.02 5 NBK7_SCHOTT\n  CIR 10\nS -0.02 40\n  CIR 10\nSI 0 0\nWHAT 1\n", "seq");
    EXPECT_EQ(seq.group["elements"][0]["front"]["radius"], 50.0);
    EXPECT_EQ(seq.group["elements"][0]["material"]["glass"], "SCHOTT:N-BK7");
    ASSERT_EQ(seq.warnings.size(), 2u);
    EXPECT_EQ(seq.warnings[0].line, 2);
    EXPECT_EQ(seq.warnings[0].message, "glass 'NBK7_SCHOTT' read as N-BK7 (SCHOTT)");
    EXPECT_EQ(seq.warnings[1].line, 7);
}

TEST(LensFiles, MissingSemiAperturesComeFromTheParaxialMarginalRay) {
    // The triplet's first element with the stop on its back face and no CIR: the stop's
    // semi-aperture is the marginal ray's height there. Smith (p. 119) traces the paraxial
    // marginal ray at y = 14.6 and finds 13.724943 at surface 2 (slope -0.148315, n_d 1.61272).
    const ImportedLens lens = lens_from_text(
        "EPD 29.2\nWL 587.5618\nS 37.40 5.90 SK4_SCHOTT\nS -341.48 12.93\n  STO\nSI 0 0\n", "seq");
    EXPECT_NEAR(lens.bench["stop_semi_diameter"].get<double>(), 13.724943, 2e-5);
    EXPECT_DOUBLE_EQ(lens.group["elements"][0]["diameter"].get<double>(), 29.2);
    ASSERT_EQ(lens.warnings.size(), 1u);
    EXPECT_EQ(lens.warnings[0].message.rfind("no semi-apertures given", 0), 0u);
    // The same pupil given as an F-number, N = EFL / 29.2 with the thick lens's EFL
    // 1/f = (n - 1)(1/R1 - 1/R2 + (n - 1) t / (n R1 R2)) at n_d: the same semi-apertures.
    const double n = 1.61272, r1 = 37.40, r2 = -341.48, t = 5.90;
    const double efl = 1.0 / ((n - 1.0) * (1.0 / r1 - 1.0 / r2 + (n - 1.0) * t / (n * r1 * r2)));
    char fno[64];
    std::snprintf(fno, sizeof fno, "FNO %.12f\n", efl / 29.2);
    const ImportedLens by_fno = lens_from_text(
        std::string(fno) + "WL 587.5618\nS 37.40 5.90 SK4_SCHOTT\nS -341.48 12.93\n  STO\nSI 0 0\n",
        "seq");
    EXPECT_NEAR(by_fno.bench["stop_semi_diameter"].get<double>(), 13.724943, 2e-5);
    EXPECT_NE(by_fno.warnings[0].message.find("(entrance pupil 29."), std::string::npos)
        << by_fno.warnings[0].message;
}

// Zemax's CLAP (a circular aperture, a hard stop for rays) narrows a surface's rim below its
// DIAM; FLAP (the floating aperture written beside DIAM) is its semi-diameter where no DIAM is.
TEST(LensFiles, ZemaxClearAndFloatingApertures) {
    const std::string singlet =
        "SURF 0\n  DISZ INFINITY\nSURF 1\n  CURV 0.02\n  GLAS N-BK7\n  DISZ 5\n  %s\nSURF 2\n"
        "  CURV -0.02\n  DISZ 40\n  DIAM 10\nSURF 3\n";
    const auto with = [&](const char* aperture) {
        char text[512];
        std::snprintf(text, sizeof text, singlet.c_str(), aperture);
        return lens_from_text(text, "zmx");
    };
    // The element's diameter is twice the larger of its faces' semi-diameters.
    EXPECT_EQ(with("FLAP 0 12 0").group["elements"][0]["diameter"], 24.0);
    EXPECT_EQ(with("DIAM 8\n  FLAP 0 12 0").group["elements"][0]["diameter"], 20.0);
    EXPECT_EQ(with("DIAM 12\n  CLAP 0 11 0").group["elements"][0]["diameter"], 22.0);
    EXPECT_EQ(with("CLAP 0 11 0\n  DIAM 12").group["elements"][0]["diameter"], 22.0);
    EXPECT_TRUE(with("FLAP 0 12 0").warnings.empty());
}

}  // namespace
}  // namespace lenslab
