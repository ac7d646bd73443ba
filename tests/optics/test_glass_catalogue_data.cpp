// Every glass of the six makers' catalogues (data/glass, converted from the refractiveindex.info
// database) against the n_d and V_d printed in the same data, and spot checks against the
// makers' published data sheets.
//
// Wavelength convention: the makers fit their formulas to indices measured relative to air at
// air wavelengths (the database copies the makers' Zemax catalogues, which are in air), so n_d
// is the formula at 587.5618 nm in air; evaluating it at the vacuum d line (587.7247 nm) would
// move n_d by about 1e-5 and break the 5e-6 agreement below.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "optics/glass_library.h"

namespace lenslab {
namespace {

struct CatalogueTolerance {
    double n_d, v_d;
};

// The catalogue values each maker prints against its own formula. SCHOTT, OHARA, CDGM and
// HIKARI print n_d computed from the formula (OHARA, CDGM, HIKARI to 6 decimals): 5e-6 and
// 0.01. HOYA prints n_d to 5 decimals, so rounding alone is 5e-6 (FDS18: formula 1.9459454,
// printed 1.94595). SUMITA prints nominal values (n_d to 4-5 decimals, V_d to 1) that its
// formulas, fitted to melts, reproduce only to 3.8e-5 (K-PSFn214(M)) and 0.23 (K-CaFK95).
const std::map<std::string, CatalogueTolerance>& catalogue_tolerances() {
    static const std::map<std::string, CatalogueTolerance> t{
        {"SCHOTT", {5e-6, 0.01}}, {"OHARA", {5e-6, 0.01}}, {"CDGM", {5e-6, 0.01}},
        {"HIKARI", {5e-6, 0.01}}, {"HOYA", {6e-6, 0.01}},  {"SUMITA", {4e-5, 0.25}}};
    return t;
}

bool covers_the_fraunhofer_lines(const Glass& g) {
    return g.model->min_nm <= kLineF && g.model->max_nm >= kLineC;
}

TEST(GlassCatalogueData, EveryGlassReproducesItsCatalogueNdAndVd) {
    const auto& glasses = maker_glasses();
    size_t checked = 0;
    std::map<std::string, size_t> per_maker;
    for (const Glass& g : glasses) {
        ++per_maker[g.maker];
        if (!std::isfinite(g.datasheet_n_d) || !covers_the_fraunhofer_lines(g)) continue;
        // SCHOTT's BOROFLOAT 33 data pairs a formula with brochure values (n_d 1.471, V_d 65.41)
        // from another source: a known disagreement of the database, checked to stay one.
        if (g.maker == "SCHOTT" && g.name == "BOROFLOAT33") {
            EXPECT_GT(std::abs(g.model->n_d() - g.datasheet_n_d), 1e-4);
            continue;
        }
        SCOPED_TRACE(g.maker + ":" + g.name);
        const CatalogueTolerance tol = catalogue_tolerances().at(g.maker);
        EXPECT_NEAR(g.model->n_d(), g.datasheet_n_d, tol.n_d);
        EXPECT_NEAR(g.model->abbe_number(), g.datasheet_v_d, tol.v_d);
        ++checked;
    }
    // The converted catalogues (tools/convert_glass_catalogues.py): 1,635 glasses, of which
    // 1,625 have catalogue values and a formula over the C-F lines (BOROFLOAT33 aside).
    EXPECT_EQ(per_maker["SCHOTT"], 170u);
    EXPECT_EQ(per_maker["OHARA"], 410u);
    EXPECT_EQ(per_maker["CDGM"], 314u);
    EXPECT_EQ(per_maker["HOYA"], 190u);
    EXPECT_EQ(per_maker["HIKARI"], 375u);
    EXPECT_EQ(per_maker["SUMITA"], 176u);
    EXPECT_EQ(checked, 1625u);
}

TEST(GlassCatalogueData, EveryModelIsFiniteAndNormallyDispersiveOverItsVisibleRange) {
    for (const Glass& g : maker_glasses()) {
        const double lo = std::max(g.model->min_nm, 400.0), hi = std::min(g.model->max_nm, 700.0);
        for (double nm = lo; nm + 50.0 <= hi; nm += 50.0) {
            const double n = g.model->n(nm);
            ASSERT_TRUE(std::isfinite(n) && n > 1.0) << g.maker << ":" << g.name << " at " << nm;
            EXPECT_GT(n, g.model->n(nm + 50.0)) << g.maker << ":" << g.name << " at " << nm;
        }
    }
}

struct PublishedGlass {
    const char* name;  // MAKER:NAME
    double n_d, v_d;
    double n_f, n_c;  // 0 where only n_d and V_d are quoted
};

TEST(GlassCatalogueData, SpotChecksAgainstTheMakersDataSheets) {
    // Values from the makers' data sheets, not from the converted data:
    //   SCHOTT N-BK7 (517642.251): n_d 1.51680, V_d 64.17, n_F 1.52238, n_C 1.51432.
    //   SCHOTT N-SF10 (728285.305): n_d 1.72828, V_d 28.53 (SF10, the lead flint it replaced,
    //   is 1.72825 / 28.41).
    //   SCHOTT F2 (620364.360): n_d 1.62004, V_d 36.37.
    //   OHARA S-BSL7: n_d 1.51633, V_d 64.14, n_F 1.52191, n_C 1.51386.
    //   CDGM H-K9L: n_d 1.51680, V_d 64.20.   HOYA BSC7: n_d 1.51680, V_d 64.20.
    //   SUMITA K-BK7: n_d 1.51633, V_d 64.1.
    const PublishedGlass published[] = {
        {"SCHOTT:N-BK7", 1.51680, 64.17, 1.52238, 1.51432},
        {"SCHOTT:N-SF10", 1.72828, 28.53, 0, 0},
        {"SCHOTT:SF10", 1.72825, 28.41, 0, 0},
        {"SCHOTT:F2", 1.62004, 36.37, 0, 0},
        {"OHARA:S-BSL7", 1.51633, 64.14, 1.52191, 1.51386},
        {"CDGM:H-K9L", 1.51680, 64.20, 0, 0},
        {"HOYA:BSC7", 1.51680, 64.20, 0, 0},
        {"SUMITA:K-BK7", 1.51633, 64.1, 0, 0},
    };
    for (const PublishedGlass& p : published) {
        SCOPED_TRACE(p.name);
        const Glass* g = find_glass(p.name);
        ASSERT_NE(g, nullptr);
        // Data sheets round n to 5 decimals and V_d to 2 (SUMITA to 1).
        EXPECT_NEAR(g->model->n_d(), p.n_d, 1e-5);
        EXPECT_NEAR(g->model->abbe_number(), p.v_d, 0.06);
        if (p.n_f > 0) {
            EXPECT_NEAR(g->model->n(kLineF), p.n_f, 1.5e-5);
            EXPECT_NEAR(g->model->n(kLineC), p.n_c, 1.5e-5);
        }
    }
}

TEST(GlassCatalogueData, TheBuiltInSchottGlassesAgreeWithTheCatalogue) {
    // The built-in N-BK7, N-SF11, F2, N-SF6, SF5 and N-FK51A copy the SCHOTT data sheets; the
    // converted SCHOTT catalogue must give the same indices across the visible.
    for (const char* name : {"N-BK7", "N-SF11", "F2", "SF5", "N-FK51A"}) {
        const Glass* builtin = find_glass(name);
        const Glass* schott = find_glass(std::string("SCHOTT:") + name);
        ASSERT_NE(builtin, nullptr);
        ASSERT_NE(schott, nullptr) << name;
        EXPECT_TRUE(builtin->maker.empty());
        EXPECT_EQ(schott->maker, "SCHOTT");
        for (double nm = 400; nm <= 700; nm += 50)
            EXPECT_NEAR(builtin->model->n(nm), schott->model->n(nm), 1e-6) << name << " " << nm;
    }
}

}  // namespace
}  // namespace lenslab
