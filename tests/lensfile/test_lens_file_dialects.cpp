// Lens files as designers write them rather than as the readers' first cases did: glass names
// lenslab knows by another name, CODE V's glass codes, line continuations, edge apertures,
// obscurations, and files that leave radius or curvature mode unsaid.
//
// The conventions, as CODE V and Zemax files use them (and as the rayoptics project's CODE V
// reader, by a former CODE V developer, reads them):
//   - a glass code in place of a CODE V glass name is a model glass: NNNVVV is n_d 1.NNN and
//     V_d VV.V (517642: 1.517, 64.2, the international glass code); NNNNNN.VVVV is CODE V's
//     fictitious glass, n_d 1.NNNNNN and V_d VV.VV (517000.520000: 1.517, 52.0).
//   - '&' at the end of a CODE V line continues the command on the next line.
//   - CIR EDG is the edge (mechanical) aperture, CIR OBS an obscuration, CIR HOL a hole; a
//     qualifier Sk names the surface.
//   - RDM (or RDM Y) reads the numbers after S as radii, RDM N as curvatures.
//   - Zemax's OBSC r R is a circular obscuration from radius r to R.
//   - SCHOTT's N-BK7 replaced BK7 (same n_d 1.5168, V_d 64.17); Zemax's SILICA is fused silica.

#include <gtest/gtest.h>

#include <cmath>

#include "lensfile/lens_file_glass.h"
#include "lensfile/lens_file_text.h"
#include "lensfile/lens_group_from_prescription.h"
#include "lensfile/seq_reader.h"
#include "lensfile/zmx_reader.h"

namespace lenslab {
namespace {

LensFilePrescription dialect_prescription(const std::string& text, const std::string& format) {
    const std::string file = "test." + format;
    const std::vector<std::string> lines = decode_lens_file_lines(text, file);
    return format == "zmx" ? read_zmx(lines, file) : read_seq(lines, file);
}

ImportedLens dialect_lens(const std::string& text, const std::string& format) {
    return lens_group_from_prescription(dialect_prescription(text, format), "test");
}

std::string dialect_error(const std::string& text, const std::string& format) {
    try {
        (void)dialect_lens(text, format);
    } catch (const LensFileError& e) {
        return e.what();
    }
    return "";
}

// A CODE V singlet (R 50, -50, 5 thick, 10 semi-aperture) of the glass `glass`; line 1.
std::string dialect_seq_singlet(const std::string& glass) {
    return "S 50 5 " + glass + "\n  CIR 10\nS -50 40\n  CIR 10\nSI 0 0\n";
}

// A Zemax singlet of the glass `glass`, the catalogues `gcat`; GLAS on line 6.
std::string dialect_zmx_singlet(const std::string& glass, const std::string& gcat = "SCHOTT") {
    return "GCAT " + gcat + "\nSURF 0\n  DISZ INFINITY\nSURF 1\n  CURV 0.02\n  GLAS " + glass +
           "\n  DISZ 5\n  DIAM 10\nSURF 2\n  CURV -0.02\n  DISZ 40\n  DIAM 10\nSURF 3\n";
}

TEST(LensFileDialects, GlassNamesUsersWriteAreReadAsLenslabsGlassWithAWarning) {
    const struct {
        std::string glass, format, material, warning;
    } cases[] = {
        {"BK7", "zmx", "SCHOTT:N-BK7",
         "glass 'BK7' read as N-BK7 (SCHOTT), SCHOTT's successor to BK7 (no longer made)"},
        {"BK7_SCHOTT", "seq", "SCHOTT:N-BK7",
         "glass 'BK7_SCHOTT' read as N-BK7 (SCHOTT), SCHOTT's successor to BK7 (no longer made)"},
        {"SILICA", "zmx", "fused-silica", "glass 'SILICA' read as fused-silica (fused silica)"},
        {"SILICA_SPECIAL", "seq", "fused-silica",
         "glass 'SILICA_SPECIAL' read as fused-silica (fused silica)"},
        {"L-TIM28_MOLD", "zmx", "OHARA:L-TIM28",
         "glass 'L-TIM28_MOLD' read as L-TIM28 (OHARA), the glass it is moulded from (lenslab "
         "has no data for the moulded state)"},
        {"L-TIM28-MOLD_OHARA", "seq", "OHARA:L-TIM28",
         "glass 'L-TIM28-MOLD_OHARA' read as L-TIM28 (OHARA), the glass it is moulded from "
         "(lenslab has no data for the moulded state)"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.glass);
        const bool zmx = c.format == "zmx";
        const ImportedLens lens = dialect_lens(
            zmx ? dialect_zmx_singlet(c.glass) : dialect_seq_singlet(c.glass), c.format);
        EXPECT_EQ(lens.group["elements"][0]["material"]["glass"], c.material);
        ASSERT_EQ(lens.warnings.size(), 1u);
        EXPECT_EQ(lens.warnings[0].line, zmx ? 6 : 1);
        EXPECT_EQ(lens.warnings[0].message, c.warning);
    }
    // BK7 of another maker is not SCHOTT's: that maker's BK7 glasses are suggested.
    EXPECT_EQ(dialect_error(dialect_seq_singlet("BK7_HIKARI"), "seq"),
              "test.seq:1: unknown glass 'BK7'; did you mean E-BK7 (HIKARI), J-BK7 (HIKARI)?");
}

TEST(LensFileDialects, UnknownGlassesSuggestNamesAsUsersNameGlasses) {
    // An old SCHOTT name: its lead-free N- successor, not the names a letter away.
    EXPECT_EQ(dialect_error(dialect_zmx_singlet("BAK1"), "zmx"),
              "test.zmx:6: unknown glass 'BAK1'; did you mean N-BAK1 (SCHOTT)?");
    // A maker's prefix is kept: CDGM's D- (moulding) glasses first.
    EXPECT_EQ(dialect_error(dialect_zmx_singlet("D-ZK3M", "CDGM"), "zmx"),
              "test.zmx:6: unknown glass 'D-ZK3M'; did you mean D-ZK3 (CDGM), D-ZK3L (CDGM)?");
    EXPECT_EQ(dialect_error(dialect_zmx_singlet("NOSUCHGLASS"), "zmx"),
              "test.zmx:6: unknown glass 'NOSUCHGLASS' (see `lenslab glass`)");
}

TEST(LensFileDialects, CodeVGlassCodesAreModelGlasses) {
    const struct {
        std::string code;
        double n_d, V_d;
    } cases[] = {{"517642", 1.517, 64.2},
                 {"517000.520000", 1.517, 52.0},
                 {"517000.5200", 1.517, 52.0},
                 {"755201.2758", 1.755201, 27.58}};
    for (const auto& c : cases) {
        SCOPED_TRACE(c.code);
        const std::optional<LensFileGlassCode> code = lens_file_glass_code(c.code);
        ASSERT_TRUE(code);
        EXPECT_DOUBLE_EQ(code->n_d, c.n_d);
        EXPECT_DOUBLE_EQ(code->V_d, c.V_d);
    }
    EXPECT_FALSE(lens_file_glass_code("5176"));    // neither form
    EXPECT_FALSE(lens_file_glass_code("51.7"));    // too few digits for n_d
    EXPECT_FALSE(lens_file_glass_code("N-BK7"));   // a name
    EXPECT_FALSE(lens_file_glass_code("000000"));  // n_d 1: no glass

    const ImportedLens lens = dialect_lens(dialect_seq_singlet("517000.520000"), "seq");
    const auto& ior = lens.group["elements"][0]["material"]["ior"];
    EXPECT_EQ(ior["model"], "abbe");
    EXPECT_DOUBLE_EQ(ior["n_d"].get<double>(), 1.517);
    EXPECT_DOUBLE_EQ(ior["V_d"].get<double>(), 52.0);
    ASSERT_EQ(lens.warnings.size(), 1u);
    EXPECT_EQ(lens.warnings[0].message,
              "glass '517000.520000' read as a model glass of n_d 1.517 and V_d 52 (a CODE V "
              "glass code)");
    // GLA takes a code too; a number that is no code is refused.
    const LensFilePrescription p =
        dialect_prescription("S 50 5 N-BK7_SCHOTT\n  GLA 517642\nS -50 40\nSI 0 0\n", "seq");
    EXPECT_EQ(p.surfaces[1].glass, "");
    EXPECT_DOUBLE_EQ(p.surfaces[1].model_nd, 1.517);
    EXPECT_DOUBLE_EQ(p.surfaces[1].model_vd, 64.2);
    EXPECT_EQ(dialect_error(dialect_seq_singlet("5176"), "seq")
                  .rfind("test.seq:1: glass '5176': a number, but not a glass code", 0),
              0u);
}

TEST(LensFileDialects, CodeVLinesEndingInAnAmpersandGoOnInTheNext) {
    const LensFilePrescription p = dialect_prescription(
        "WL 656.2725 &  ! red\n   587.5618 &\n   486.1327\nS 50 5 N-BK7_SCHOTT\nSI 0 0\n", "seq");
    EXPECT_EQ(p.wavelengths_nm, (std::vector<double>{656.2725, 587.5618, 486.1327}));
    EXPECT_EQ(p.surfaces[1].line, 4);  // lines counted as in the file
    // A message about a continued command names its first line.
    EXPECT_EQ(dialect_error("EPD 10\nS 50 5 &\n  N-BK77_SCHOTT\nS -50 40\nSI 0 0\n", "seq")
                  .rfind("test.seq:2: unknown glass 'N-BK77'", 0),
              0u);
}

TEST(LensFileDialects, CodeVEdgeAperturesObscurationsAndHoles) {
    const LensFilePrescription p = dialect_prescription(
        "S 50 5 N-BK7_SCHOTT\n  CIR EDG 12\n"      // 1-2: an edge aperture only
        "S -50 40\n  CIR 10; CIR EDG 12\n"         // 3-4: clear and edge
        "S 0 1\n  CIR OBS 3\n  CIR 8\n"            // 5-7: an obscuration
        "S 0 1\n  CIR HOL 1\nCIR S4 9\nSI 0 0\n",  // 8-11: a hole; surface 4 by its number
        "seq");
    ASSERT_EQ(p.surfaces.size(), 6u);
    EXPECT_EQ(p.surfaces[1].semi_diameter, 12.0);
    EXPECT_EQ(p.surfaces[2].semi_diameter, 10.0);
    EXPECT_EQ(p.surfaces[3].semi_diameter, 8.0);
    EXPECT_EQ(p.surfaces[3].obscuration_semi_diameter, 3.0);
    EXPECT_EQ(p.surfaces[4].semi_diameter, 9.0);
    ASSERT_EQ(p.warnings.size(), 3u);
    EXPECT_EQ(p.warnings[0].line, 6);
    EXPECT_EQ(p.warnings[0].message,
              "CIR OBS: a central obscuration of radius 3 on surface 3; on a mirror, its central "
              "hole; elsewhere recorded, but not yet used (no ray is blocked by it)");
    EXPECT_EQ(p.warnings[1].line, 9);
    EXPECT_EQ(p.warnings[1].message.rfind("CIR HOL: a hole of radius 1 on surface 4", 0), 0u);
    EXPECT_EQ(p.warnings[2].line, 2);
    EXPECT_EQ(p.warnings[2].message,
              "CIR EDG: surface 1 has no clear aperture (CIR); its edge aperture 12 is taken as "
              "its semi-diameter");
}

TEST(LensFileDialects, ZemaxCentralObscurationsAreRecorded) {
    std::string text = dialect_zmx_singlet("N-BK7");
    text.replace(text.find("SURF 2\n"), 7, "SURF 2\n  OBSC 0 4.5 0\n");
    const LensFilePrescription p = dialect_prescription(text, "zmx");
    EXPECT_EQ(p.surfaces[2].obscuration_semi_diameter, 4.5);
    ASSERT_EQ(p.warnings.size(), 1u);
    EXPECT_EQ(p.warnings[0].line, 10);
    EXPECT_EQ(p.warnings[0].message.rfind("OBSC: a central obscuration of radius 4.5", 0), 0u);
    // A record left at its defaults obscures nothing.
    text.replace(text.find("OBSC 0 4.5 0"), 12, "OBSC 0 0 0");
    EXPECT_TRUE(dialect_prescription(text, "zmx").warnings.empty());
}

TEST(LensFileDialects, CodeVFilesWithoutRdmAreRadiiUnlessOnlyCurvaturesMakeSense) {
    // As radii, 0.02 cannot reach the entrance pupil's 5 mm radius at surface 1: curvatures.
    const std::string curvatures = "EPD 10\nSO 0 1e10\nS 0.02 5 N-BK7_SCHOTT\nS -0.02 40\nSI 0 0\n";
    const ImportedLens lens = dialect_lens(curvatures, "seq");
    EXPECT_DOUBLE_EQ(lens.group["elements"][0]["front"]["radius"].get<double>(), 50.0);
    EXPECT_DOUBLE_EQ(lens.group["elements"][0]["back"]["radius"].get<double>(), -50.0);
    ASSERT_EQ(lens.warnings.size(), 2u);  // and the semi-apertures' estimate
    EXPECT_EQ(lens.warnings[1].line, 3);
    EXPECT_EQ(lens.warnings[1].message,
              "no RDM: the numbers after S are read as curvatures, as after RDM N (as radii, "
              "surface 1's 0.02 cannot reach its semi-aperture 5); write RDM N or RDM Y to say "
              "which");
    // Without apertures: faces far more curved than their glass is thick (rayoptics' singlet).
    const LensFilePrescription singlet =
        dialect_prescription("SO 0 100\nS 0.1 1 NBK7_SCHOTT\nS -0.05 15\nSI 0 0\nFNO 5\n", "seq");
    EXPECT_DOUBLE_EQ(singlet.surfaces[1].radius, 10.0);
    EXPECT_DOUBLE_EQ(singlet.surfaces[2].radius, -20.0);
    // Said outright, the mode is obeyed; RDM NO is RDM N.
    EXPECT_EQ(dialect_prescription("RDM\n" + curvatures, "seq").surfaces[1].radius, 0.02);
    EXPECT_EQ(dialect_prescription("RDM YES\n" + curvatures, "seq").surfaces[1].radius, 0.02);
    EXPECT_EQ(dialect_prescription("RDM NO\n" + curvatures, "seq").surfaces[1].radius, 50.0);
    EXPECT_TRUE(dialect_prescription("RDM NO\n" + curvatures, "seq").warnings.empty());
    EXPECT_EQ(dialect_error("RDM MAYBE\n" + curvatures, "seq"),
              "test.seq:1: RDM 'MAYBE': Y (radii) or N (curvatures)");
    // The rayoptics landscape lens: a flat face, then -0.2, behind a 1 mm entrance pupil: the
    // marginal ray still at 0.5 from the axis there, so -0.2 is a curvature (radius -5).
    const LensFilePrescription landscape = dialect_prescription(
        "so 0. 1.0e+10\ns 0. 1.664\nsto\ns -0.2 0.22 NBK7_SCHOTT\ns -0.387040626 10.150245\n"
        "si 0 0\nepd 1.0\n",
        "seq");
    EXPECT_DOUBLE_EQ(landscape.surfaces[2].radius, -5.0);
    // INF stands for an infinite distance, as 1e10 does.
    EXPECT_TRUE(std::isinf(dialect_prescription("SO 0 inf\nS 50 5 N-BK7_SCHOTT\nSI 0 0\n", "seq")
                               .surfaces[0]
                               .thickness));
    // Radii that make sense stay radii, without a warning.
    const LensFilePrescription radii =
        dialect_prescription("EPD 10\nSO 0 1e10\nS 50 5 N-BK7_SCHOTT\nS -50 40\nSI 0 0\n", "seq");
    EXPECT_EQ(radii.surfaces[1].radius, 50.0);
    EXPECT_TRUE(radii.warnings.empty());
}

}  // namespace
}  // namespace lenslab

namespace lenslab {
namespace {

// Zemax's RAIM line: its second number is the ray aiming, 0 off (rays aimed at the paraxial
// entrance pupil), 1 paraxial and 2 real (both through the stop); the bench keeps it.
TEST(LensFileDialects, ZemaxRayAimingIsKeptForTheBench) {
    const std::string singlet = dialect_zmx_singlet("N-BK7");
    EXPECT_FALSE(dialect_lens(singlet, "zmx").bench.contains("ray_aiming"));
    EXPECT_EQ(dialect_lens("RAIM 0 0 1 1 0 0 0 0 0\n" + singlet, "zmx").bench["ray_aiming"],
              "paraxial");
    EXPECT_EQ(dialect_lens("RAIM 0 2 1 1 0 1 0 0 0\n" + singlet, "zmx").bench["ray_aiming"],
              "real");
    EXPECT_EQ(dialect_lens("RAIM 0 1 1 1 0 0 0 0 0 1\n" + singlet, "zmx").bench["ray_aiming"],
              "real");
}

// The open tools write a model glass as n_d:V_d; older files are ISO-8859-1; a flat base with
// aspheric terms (a Schmidt plate) becomes a sag formula in r.
TEST(LensFileDialects, ModelGlassesLatin1TextAndFlatBaseAspheres) {
    const LensFilePrescription p = dialect_prescription(dialect_seq_singlet("1.5168:64.17"), "seq");
    EXPECT_EQ(p.surfaces[1].glass, "");
    EXPECT_EQ(p.surfaces[1].model_nd, 1.5168);
    EXPECT_EQ(p.surfaces[1].model_vd, 64.17);
    std::string latin1 = dialect_zmx_singlet("N-BK7");
    latin1.insert(0, "NAME lens \xD8 25 mm\n");
    EXPECT_EQ(dialect_prescription(latin1, "zmx").surfaces.size(), 4u);
    const std::vector<std::string> lines = decode_lens_file_lines(latin1, "t.zmx");
    EXPECT_EQ(lines[0], "NAME lens \u00D8 25 mm");
    const ImportedLens plate = dialect_lens(
        "EPD 10\nS 0 5 N-BK7_SCHOTT\n  CIR 10\n  ASP\n  K 0; A 2.5e-5; B -1e-8\nS 0 40\n"
        "  CIR 10\nSI 0 0\n",
        "seq");
    const nlohmann::json front = nlohmann::json(plate.group)["elements"][0]["front"];
    EXPECT_EQ(front["shape"], "sag");
    EXPECT_EQ(front["formula"], "(2.5000000000000001e-05)*r^4 + (-1e-08)*r^6");
}

}  // namespace
}  // namespace lenslab
