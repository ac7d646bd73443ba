// Reading a user's Zemax AGF glass catalogue: a hand-written N-BK7 entry against SCHOTT's
// published n_d and V_d, every formula number against Zemax's formula written out, the
// encodings, and one clear error with the line for each kind of bad file.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "optics/absorption.h"
#include "optics/agf_catalogue.h"
#include "optics/glass_catalogue_file.h"
#include "optics/glass_library.h"
#include "optics/user_glass_catalogues.h"
#include "scene/scene_json.h"
#include "util/scene_error.h"

namespace lenslab {
namespace {

// SCHOTT's N-BK7 as its AGF catalogue writes it: Sellmeier 1 (formula 2) with the data
// sheet's B1, C1, B2, C2, B3, C3, range 0.3-2.5 um, and tau_i(10 mm) = 0.997 at 400 nm.
const char* const kAgfBk7 =
    "CC hand-written test catalogue\r\n"
    "NM N-BK7 2 517642.251 1.5168 64.17 0 1\r\n"
    "GC borosilicate crown\r\n"
    "ED 7.1 8.3 2.51 -0.0009 0\r\n"
    "CD 1.03961212E+00 6.00069867E-03 2.31792344E-01 2.00179144E-02 1.01046945E+00 "
    "1.03560653E+02 0 0 0 0\r\n"
    "TD 1.86E-06 1.31E-08 -1.37E-11 4.34E-07 6.27E-10 1.7E-01 2.0E+01\r\n"
    "OD 1 1 0 1 2.3 2.3\r\n"
    "LD 3.0E-01 2.5E+00\r\n"
    "IT 4.0E-01 9.97E-01 1.0E+01\r\n"
    "IT 5.0E-01 9.98E-01 1.0E+01\r\n";

std::vector<Glass> agf(const std::string& text) { return parse_agf_catalogue(text, "t.agf", "T"); }

TEST(AgfCatalogue, SchottBk7GivesTheDataSheetValues) {
    // SCHOTT data sheet N-BK7 (517642.251): n_d = 1.51680, V_d = 64.17.
    const std::vector<Glass> glasses = agf(kAgfBk7);
    ASSERT_EQ(glasses.size(), 1u);
    const Glass& g = glasses[0];
    EXPECT_EQ(g.name, "N-BK7");
    EXPECT_EQ(g.maker, "T");
    EXPECT_NEAR(g.model->n_d(), 1.51680, 5e-6);
    EXPECT_NEAR(g.model->abbe_number(), 64.17, 0.01);
    EXPECT_EQ(g.datasheet_n_d, 1.5168);
    EXPECT_EQ(g.model->min_nm, 300.0);
    EXPECT_EQ(g.model->max_nm, 2500.0);
    // The IT lines come back as the internal transmittance they give.
    EXPECT_NEAR(internal_transmittance(g.k_um, 400, 10), 0.997, 1e-9);
    EXPECT_NEAR(internal_transmittance(g.k_um, 500, 10), 0.998, 1e-9);
}

TEST(AgfCatalogue, Utf16WithByteOrderMarkReadsTheSame) {
    const std::string ascii = kAgfBk7;
    std::string le = "\xFF\xFE";
    for (char c : ascii) le.append({c, '\0'});
    std::string be = "\xFE\xFF";
    for (char c : ascii) be.append({'\0', c});
    for (const std::string& text : {le, be}) {
        const std::vector<Glass> g = agf(text);
        ASSERT_EQ(g.size(), 1u);
        EXPECT_NEAR(g[0].model->n_d(), 1.51680, 5e-6);
    }
}

// Zemax's formulas written out (OpticStudio manual, "Glass catalogs": dispersion formulas),
// l in um, to check each number maps onto the right form.
double zemax_formula(int formula, const std::vector<double>& c, double l) {
    const double l2 = l * l;
    switch (formula) {
        case 1:
            return std::sqrt(c[0] + c[1] * l2 + c[2] / l2 + c[3] / std::pow(l, 4) +
                             c[4] / std::pow(l, 6) + c[5] / std::pow(l, 8));
        case 2:
            return std::sqrt(1 + c[0] * l2 / (l2 - c[1]) + c[2] * l2 / (l2 - c[3]) +
                             c[4] * l2 / (l2 - c[5]));
        case 3: {
            const double big_l = 1 / (l2 - 0.028);
            return c[0] + c[1] * big_l + c[2] * big_l * big_l + c[3] * l2 + c[4] * l2 * l2 +
                   c[5] * l2 * l2 * l2;
        }
        case 4:
            return std::sqrt(1 + c[0] + c[1] * l2 / (l2 - c[2] * c[2]) + c[3] / (l2 - c[4] * c[4]));
        case 5:
            return c[0] + c[1] / l + c[2] / std::pow(l, 3.5);
        case 6:
            return std::sqrt(1 + c[0] * l2 / (l2 - c[1]) + c[2] * l2 / (l2 - c[3]) +
                             c[4] * l2 / (l2 - c[5]) + c[6] * l2 / (l2 - c[7]));
        case 7:
            return std::sqrt(c[0] + c[1] / (l2 - c[2]) - c[3] * l2);
        case 8:
            return std::sqrt(c[0] + c[1] * l2 / (l2 - c[2]) - c[3] * l2);
        case 9:
            return std::sqrt(c[0] + c[1] * l2 / (l2 - c[2]) + c[3] * l2 / (l2 - c[4]));
        case 10:
            return std::sqrt(c[0] + c[1] * l2 + c[2] / l2 + c[3] / std::pow(l, 4) +
                             c[4] / std::pow(l, 6) + c[5] / std::pow(l, 8) +
                             c[6] / std::pow(l, 10) + c[7] / std::pow(l, 12));
        case 11:
            return std::sqrt(1 + c[0] * l2 / (l2 - c[1]) + c[2] * l2 / (l2 - c[3]) +
                             c[4] * l2 / (l2 - c[5]) + c[6] * l2 / (l2 - c[7]) +
                             c[8] * l2 / (l2 - c[9]));
        case 12:
            return std::sqrt(c[0] + c[1] * l2 + c[2] / l2 + c[3] / std::pow(l, 4) +
                             c[4] / std::pow(l, 6) + c[5] / std::pow(l, 8) + c[6] * l2 * l2 +
                             c[7] * l2 * l2 * l2);
        case 13:
            return std::sqrt(c[0] + c[1] * l2 + c[2] * l2 * l2 + c[3] / l2 + c[4] / std::pow(l, 4) +
                             c[5] / std::pow(l, 6) + c[6] / std::pow(l, 8) +
                             c[7] / std::pow(l, 10) + c[8] / std::pow(l, 12));
    }
    return NAN;
}

TEST(AgfCatalogue, EveryFormulaNumberIsZemaxs) {
    // Coefficients of the right size for each form (not a real glass: the mapping is tested).
    const std::vector<std::vector<double>> coefficients = {
        {2.27, -0.0101, 0.0106, 2.08e-4, -7.6e-6, 4.9e-7},                      // 1
        {1.0396, 0.0060, 0.2318, 0.0200, 1.0105, 103.56},                       // 2
        {1.50, 0.005, 2e-4, -0.002, 1e-5, -1e-7},                               // 3
        {0.2, 1.0, 0.1, 0.003, 0.15},                                           // 4
        {1.50, 0.004, 0.0003},                                                  // 5
        {1.0, 0.006, 0.2, 0.02, 1.0, 100, 0.01, 0.03},                          // 6
        {2.27, 0.0105, 0.012, 0.0101},                                          // 7
        {1.3, 0.98, 0.011, 0.009},                                              // 8
        {1.2, 1.0, 0.008, 1.0, 100},                                            // 9
        {2.27, -0.0101, 0.0106, 2.08e-4, -7.6e-6, 4.9e-7, 1e-8, -1e-9},         // 10
        {1.0, 0.006, 0.2, 0.02, 0.9, 100, 0.01, 0.03, 0.005, 0.04},             // 11
        {2.27, -0.0101, 0.0106, 2.08e-4, -7.6e-6, 4.9e-7, 1e-4, -1e-5},         // 12
        {2.27, -0.0101, 1e-4, 0.0106, 2.08e-4, -7.6e-6, 4.9e-7, 1e-8, -1e-9}};  // 13
    for (int f = 1; f <= 13; ++f) {
        SCOPED_TRACE("formula " + std::to_string(f));
        const auto& c = coefficients[static_cast<size_t>(f - 1)];
        const IndexModelPtr m = agf_formula_index(f, c, 0.35, 2.5);
        for (double l : {0.4, 0.5876, 0.7})
            EXPECT_NEAR(m->n(l * 1e3), zemax_formula(f, c, l), 1e-12);
    }
}

// The error text of a bad catalogue.
std::string agf_error(const std::string& text) {
    try {
        agf(text);
    } catch (const GlassDataError& e) {
        return e.what();
    }
    return "(accepted)";
}

TEST(AgfCatalogue, BadFilesAreRefusedWithTheLine) {
    EXPECT_EQ(agf_error("NM A 2 0 1.5 60\nCD 1 0.01 0 0 0 0\nXX 1 2\n"),
              "t.agf:3: unknown line 'XX' (an AGF file has NM, CD, LD, IT, CC, GC, ED, TD, OD, "
              "BD lines)");
    EXPECT_EQ(agf_error("NM A 14 0 1.5 60\n"),
              "t.agf:1: dispersion formula 14 is not one of Zemax's formulas 1-13");
    EXPECT_EQ(agf_error("NM A 2 0 1.5 60\nCD 1 0.01 x\n"),
              "t.agf:2: a CD coefficient must be a number, got 'x'");
    EXPECT_EQ(agf_error("CC c\nNM A 2 0 1.5 60\nLD 0.3 2.5\n"),
              "t.agf:2: glass A has no CD line (its coefficients)");
    EXPECT_EQ(agf_error("CD 1 2 3\n"), "t.agf:1: 'CD' line before the first NM (glass) line");
    EXPECT_EQ(agf_error("NM A 2 0 1.5 60\nCD 1 0.01 0 0 0 0\nLD 2.5 0.3\n"),
              "t.agf:3: LD range must be 0 < min < max (um)");
    EXPECT_EQ(agf_error("CC only comments\n"), "t.agf: no glass (NM line) in the file");
    // UTF-16 without a byte order mark cannot be told from binary junk.
    EXPECT_EQ(agf_error(std::string("N\0M\0", 4)),
              "t.agf:1: holds NUL characters: UTF-16 without a byte order mark is not read");
    EXPECT_NE(agf_error("NM A 2 0 1.5 60\nIT 0.4 0.9\n").find("t.agf:2: missing the IT thickness"),
              std::string::npos);
}

TEST(AgfCatalogue, ASceneNamesItsCataloguesGlasses) {
    // The file beside the scene, named relative to it; its glasses by NAME or FILE:NAME.
    const auto dir = std::filesystem::temp_directory_path() / "lenslab_test_agf_scene";
    std::filesystem::create_directories(dir);
    {
        std::ofstream out(dir / "mine.agf", std::ios::binary);
        out << "NM MY-CROWN 2 517642 1.5168 64.17 0 1\n"
               "CD 1.03961212 0.00600069867 0.231792344 0.0200179144 1.01046945 103.560653\n"
               "LD 0.3 2.5\n";
    }
    const Scene scene = parse_scene(R"({"glass_catalogues": ["mine.agf"],
        "camera": {"position": [0, 0, -5], "look_at": [0, 0, 0]},
        "materials": {"a": {"transparency": 1, "glass": "my-crown"},
                      "b": {"transparency": 1, "glass": "MINE:MY-CROWN"}}})",
                                    "scene.json", dir.string());
    EXPECT_NEAR(scene.materials[0].ior(587.5618), 1.51680, 5e-6);
    EXPECT_EQ(scene.materials[0].glass, "MINE:MY-CROWN");
    EXPECT_EQ(scene.materials[1].index, scene.materials[0].index);
    try {
        parse_scene(R"({"glass_catalogues": ["absent.agf"],
            "camera": {"position": [0, 0, -5], "look_at": [0, 0, 0]}})",
                    "scene.json", dir.string());
        FAIL() << "accepted a missing catalogue";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.path(), "glass_catalogues[0]");
        EXPECT_NE(e.reason().find("absent.agf: not a glass catalogue file"), std::string::npos)
            << e.reason();
    }
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace lenslab
