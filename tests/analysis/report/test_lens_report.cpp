// The report `lenslab analyze` prints: its JSON carries the figures the issue names, equal
// to the modules that compute them, with the wavelength of each; the table says the same.

#include <gtest/gtest.h>

#include "../lens_scene_builder.h"
#include "analysis/report/lens_report.h"

namespace lenslab {
namespace {

using test::lens_scene;
using test::LensSpec;
using test::sphere;

const LensSpec kLens{"LA1131", 0, 5.34, 25.4, sphere(25.75), sphere(0), test::glass("N-BK7")};

TEST(LensReport, JsonHoldsTheNamedFigures) {
    const std::string screen =
        R"({"type": "triangle", "name": "screen", "vertices": [[0, 0, 60], [1, 0, 60], [0, 1, 60]],
            "material": {"color": 0.5}})";
    const OpticalSystem system = build_optical_system(lens_scene({kLens}, {screen}));
    const LensReport r = analyze_lens_system(system, {});
    const auto j = report_json(system, r);
    for (const char* key : {"efl", "bfl", "ffl", "rms_spot_paraxial", "rms_spot_best", "best_focus",
                            "chromatic_shift_FC", "wavelength_nm", "principal_planes", "lsa",
                            "geometric_spot_best", "surfaces", "lenses", "ignored"}) {
        EXPECT_TRUE(j.contains(key)) << key;
    }
    EXPECT_DOUBLE_EQ(j["wavelength_nm"].get<double>(), kLineD);
    EXPECT_DOUBLE_EQ(j["efl"].get<double>(), paraxial_trace(system, kLineD).efl);
    EXPECT_DOUBLE_EQ(j["bfl"].get<double>(), r.paraxial.bfl);
    EXPECT_DOUBLE_EQ(j["chromatic_shift_FC"].get<double>(),
                     paraxial_trace(system, kLineF).bfl - paraxial_trace(system, kLineC).bfl);
    EXPECT_DOUBLE_EQ(j["best_focus"].get<double>(), r.spot_best.z - 5.34);
    EXPECT_DOUBLE_EQ(j["aperture_diameter"].get<double>(), 25.4);
    EXPECT_EQ(j["lsa"].size(), 20u);
    EXPECT_EQ(j["ignored"][0], "objects[1] ('screen'): not a lens");
    EXPECT_EQ(j["surfaces"][1]["radius"], nullptr);  // flat
    EXPECT_LT(j["rms_spot_best"].get<double>(), j["rms_spot_paraxial"].get<double>());
}

TEST(LensReport, TheWavelengthChangesEveryFigure) {
    // N-BK7's index falls with wavelength, so the focal length grows (SCHOTT data sheet).
    const OpticalSystem system = build_optical_system(lens_scene({kLens}));
    LensReportOptions red;
    red.wavelength_nm = 656.2725;
    const LensReport d = analyze_lens_system(system, {});
    const LensReport c = analyze_lens_system(system, red);
    EXPECT_GT(c.paraxial.efl, d.paraxial.efl);
    EXPECT_DOUBLE_EQ(c.paraxial.bfl, d.paraxial_C.bfl);
    const std::string table = report_table(system, c);
    EXPECT_NE(table.find("Paraxial, at 656.27 nm (C line)"), std::string::npos) << table;
    EXPECT_NE(table.find("Real rays, at 656.27 nm (C line)"), std::string::npos) << table;
    EXPECT_NE(table.find("F = 486.13 nm (F line), C = 656.27 nm (C line)"), std::string::npos);
}

TEST(LensReport, AGivenApertureIsUsed) {
    const OpticalSystem system = build_optical_system(lens_scene({kLens}));
    LensReportOptions narrow;
    narrow.aperture_radius = 2.0;
    const LensReport r = analyze_lens_system(system, narrow);
    EXPECT_DOUBLE_EQ(r.aperture_radius, 2.0);
    EXPECT_EQ(r.rays_lost, 0);
    // Spherical aberration grows as h^3 in the spot: a narrow beam is far sharper.
    EXPECT_LT(r.spot_best.rms_radius, 0.01 * analyze_lens_system(system, {}).spot_best.rms_radius);
}

TEST(LensReport, DefaultStopKeepsTheBeamAsTheEntrancePupil) {
    // Without stop options the stop is the first surface and the entrance pupil is the beam
    // the report has always traced, so the figures from before stops stay as they were.
    const OpticalSystem system = build_optical_system(lens_scene({kLens}));
    const LensReport r = analyze_lens_system(system, {});
    EXPECT_DOUBLE_EQ(r.first_order.entrance_pupil.diameter, 2.0 * r.aperture_radius);
    EXPECT_DOUBLE_EQ(r.first_order.entrance_pupil.position, 0.0);
    const auto j = report_json(system, r);
    for (const char* key : {"efl", "bfl", "f_number", "entrance_pupil", "exit_pupil",
                            "lagrange_invariant", "na", "working_f_number", "rays"}) {
        EXPECT_TRUE(j["first_order"].contains(key)) << key;
    }
    EXPECT_DOUBLE_EQ(j["first_order"]["f_number"].get<double>(),
                     r.paraxial.efl / (2.0 * r.aperture_radius));
    EXPECT_EQ(j["seidel"]["surfaces"].size(), 2u);
    EXPECT_TRUE(j["seidel"]["total"].contains("S_I"));
}

TEST(LensReport, WavelengthsSetThePrimaryAndTheColourPair) {
    const OpticalSystem system = build_optical_system(lens_scene({kLens}));
    LensReportOptions o;
    o.wavelength_nm = 546.074;
    o.wavelengths = {480.0, 546.074, 643.8469};
    const LensReport r = analyze_lens_system(system, o);
    EXPECT_DOUBLE_EQ(r.short_nm, 480.0);
    EXPECT_DOUBLE_EQ(r.long_nm, 643.8469);
    EXPECT_DOUBLE_EQ(r.paraxial_F.bfl, paraxial_trace(system, 480.0).bfl);
    EXPECT_DOUBLE_EQ(r.seidel.short_nm, 480.0);
    const std::string table = report_table(system, r);
    EXPECT_NE(table.find("short 480.00 nm, long 643.85 nm"), std::string::npos) << table;
}

// SCHOTT's B270 is tabulated from 435.83 to 656.27 nm, just short of the C line (656.2725
// nm): a lens of it asked about at one wavelength is measured, its chromatic block and
// Seidel colour sums reported unavailable (null) with the reason, not the lens refused.
TEST(LensReport, AColourPairOutsideAGlassRangeIsUnavailable) {
    const LensSpec b270{"window lens", 0, 5, 25, sphere(40), sphere(0), test::glass("B270")};
    const OpticalSystem system = build_optical_system(lens_scene({b270}));
    const LensReport r = analyze_lens_system(system, {});
    EXPECT_NE(r.chromatic_unavailable.find("the C line 656.273 nm is outside the validity range"),
              std::string::npos)
        << r.chromatic_unavailable;
    const auto j = report_json(system, r);
    EXPECT_TRUE(j["chromatic_shift_FC"].is_null());
    EXPECT_EQ(j["chromatic"]["unavailable"], r.chromatic_unavailable);
    EXPECT_TRUE(j["seidel"]["total"]["C_I"].is_null());
    EXPECT_GT(j["efl"].get<double>(), 0.0);
    EXPECT_NE(report_table(system, r).find("Chromatic (paraxial): unavailable"), std::string::npos);
    // Two wavelengths inside the range give the block as usual.
    LensReportOptions pair;
    pair.wavelengths = {486.1327, 587.5618};
    pair.wavelength_nm = 587.5618;
    const LensReport within = analyze_lens_system(system, pair);
    EXPECT_TRUE(within.chromatic_unavailable.empty());
    EXPECT_NE(within.chromatic_shift_FC, 0.0);
}

}  // namespace
}  // namespace lenslab
