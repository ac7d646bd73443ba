// The refractiveindex.info dispersion formulas 1-9 and tabulated n, against published values
// and hand-worked arithmetic.

#include <gtest/gtest.h>

#include <cmath>

#include "optics/dispersion_formula.h"

namespace lenslab {
namespace {

TEST(DispersionFormula, SellmeierWithPoleWavelengthsIsMalitsonFusedSilica) {
    // Formula 1 takes the pole wavelengths (um) unsquared: Malitson's fused silica,
    // J. Opt. Soc. Am. 55, 1205 (1965), tabulates n_d 1.45846.
    const auto silica = formula_index(
        1, {0, 0.6961663, 0.0684043, 0.4079426, 0.1162414, 0.8974794, 9.896161}, 0.21, 3.71);
    EXPECT_NEAR(silica->n_d(), 1.45846, 1e-5);
    EXPECT_DOUBLE_EQ(silica->min_nm, 210.0);
    EXPECT_DOUBLE_EQ(silica->max_nm, 3710.0);
}

TEST(DispersionFormula, SellmeierTwoIsTheSchottDataSheetForm) {
    // SCHOTT N-BK7 data sheet: n_d 1.51680, n_F 1.52238, n_C 1.51432.
    const auto bk7 = formula_index(
        2, {0, 1.03961212, 0.00600069867, 0.231792344, 0.0200179144, 1.01046945, 103.560653}, 0.3,
        2.5);
    EXPECT_NEAR(bk7->n_d(), 1.51680, 5e-6);
    EXPECT_NEAR(bk7->n(kLineF), 1.52238, 5e-6);
    EXPECT_NEAR(bk7->n(kLineC), 1.51432, 5e-6);
}

TEST(DispersionFormula, PolynomialIsTheSchottPowerSeries) {
    // n^2 = A0 + A1 l^2 + A2 l^-2 + ...: at l = 0.5 um, 2.25 + 0.01 * 0.25 + 0.004 / 0.25
    // = 2.2685, n = 1.506154.
    const auto p = formula_index(3, {2.25, 0.01, 2, 0.004, -2}, 0.4, 0.7);
    EXPECT_NEAR(p->n(500), std::sqrt(2.2685), 1e-12);
}

TEST(DispersionFormula, RefractiveIndexInfoFormulaReducesToSellmeier) {
    // Formula 4 with poles C2 l^2 / (l^2 - C4^2) is the two-pole Sellmeier of formula 2 plus
    // C1 - 1; its power terms add C10 l^C11.
    const auto four = formula_index(4,
                                    {1, 1.03961212, 2, std::sqrt(0.00600069867), 2, 0.231792344, 2,
                                     std::sqrt(0.0200179144), 2, -0.01, 2},
                                    0.3, 2.5);
    const auto two =
        formula_index(2, {0, 1.03961212, 0.00600069867, 0.231792344, 0.0200179144}, 0.3, 2.5);
    for (double nm : {400.0, 550.0, 700.0}) {
        const double l2 = nm * nm * 1e-6;
        EXPECT_NEAR(four->n(nm), std::sqrt(two->n(nm) * two->n(nm) - 0.01 * l2), 1e-12) << nm;
    }
}

TEST(DispersionFormula, CauchyGasesHerzbergerRetroExoticByHand) {
    // Cauchy: n = 1.5 + 0.004 l^-2 at 0.5 um = 1.516.
    EXPECT_NEAR(formula_index(5, {1.5, 0.004, -2}, 0.4, 0.7)->n(500), 1.516, 1e-12);
    // Gases, Ciddor's standard air (the database's air page): n - 1 = 0.05792105 /
    // (238.0185 - l^-2) + 0.00167917 / (57.362 - l^-2); air at the d line is 1.000277.
    const auto air = formula_index(6, {0, 0.05792105, 238.0185, 0.00167917, 57.362}, 0.23, 1.69);
    EXPECT_NEAR(air->n_d(), 1.000277, 1e-6);
    // Herzberger: n = 1.5 + 0.01 / (0.25 - 0.028) at 0.5 um = 1.545045.
    EXPECT_NEAR(formula_index(7, {1.5, 0.01}, 0.4, 0.7)->n(500), 1.5 + 0.01 / 0.222, 1e-12);
    // Retro, Lorentz-Lorenz with a constant r = 0.3: n^2 = 1.6 / 0.7.
    EXPECT_NEAR(formula_index(8, {0.3}, 0.4, 0.7)->n(500), std::sqrt(1.6 / 0.7), 1e-12);
    // Exotic: n^2 = 2.25 + 0.01 / (0.25 - 0.01) at 0.5 um.
    EXPECT_NEAR(formula_index(9, {2.25, 0.01, 0.01}, 0.4, 0.7)->n(500),
                std::sqrt(2.25 + 0.01 / 0.24), 1e-12);
}

TEST(DispersionFormula, TabulatedIndexInterpolatesLinearly) {
    const auto t = tabulated_index({{0.4, 1.53}, {0.6, 1.52}, {0.8, 1.515}});
    EXPECT_NEAR(t->n(500), 1.525, 1e-12);
    EXPECT_NEAR(t->n(700), 1.5175, 1e-12);
    EXPECT_DOUBLE_EQ(t->min_nm, 400.0);
    EXPECT_DOUBLE_EQ(t->max_nm, 800.0);
}

TEST(DispersionFormula, RefusesWhatItCannotEvaluate) {
    EXPECT_THROW(formula_index(10, {1, 2, 3}, 0.4, 0.7), DispersionDataError);
    EXPECT_THROW(formula_index(2, {0, 1.0, 0.01, 0.2}, 0.4, 0.7), DispersionDataError);
    EXPECT_THROW(formula_index(7, {1, 2, 3, 4, 5, 6, 7}, 0.4, 0.7), DispersionDataError);
    EXPECT_THROW(formula_index(2, {0, 1.0, 0.01}, 0.7, 0.4), DispersionDataError);
    EXPECT_THROW(tabulated_index({{0.5, 1.5}}), DispersionDataError);
    EXPECT_THROW(tabulated_index({{0.6, 1.5}, {0.5, 1.51}}), DispersionDataError);
    try {
        formula_index(2, {0, 1.0, 0.01, 0.2}, 0.4, 0.7);
    } catch (const DispersionDataError& e) {
        EXPECT_STREQ(e.what(),
                     "Sellmeier-2 (formula 2) takes C1 and then pairs: an odd number, at least 3 "
                     "coefficients, got 4");
    }
}

}  // namespace
}  // namespace lenslab
