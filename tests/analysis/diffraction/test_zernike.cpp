// Zernike polynomials and fits (analysis/diffraction/zernike.h) against closed forms:
// - the (n, m) of each term: Noll's table (Noll, J. Opt. Soc. Am. 66, 207 (1976), table 1)
//   and the 37-term Fringe set (Wyant & Creath, Applied Optics and Optical Engineering XI,
//   ch. 1, table 13);
// - Noll's terms are orthonormal over the unit disc (mean square 1), Fringe's are 1 at the rim;
// - a pure defocus W020 ρ² is Noll Z4 = W020/(2√3) (Fringe Z4 = W020/2) plus piston, nothing
//   else; primary spherical W040 ρ⁴ is Noll Z11 = W040/(6√5) plus the defocus W040/(2√3) and
//   piston W040/3; coma ρ³ sin θ is Noll Z7 = 1/(3√8) plus the tilt Z3 = 1/3 (Mahajan, Optical
//   Imaging and Aberrations, part II, table 4-1).

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "analysis/diffraction/zernike.h"
#include "math/constants.h"

namespace lenslab {
namespace {

PupilFunction zernike_test_pupil(double (*w)(double x, double y), int samples = 64) {
    return make_pupil({samples, 2}, 1e-3, 5, w);
}

// Every coefficient but those named is below `tolerance`.
void expect_only(const ZernikeFit& fit, std::initializer_list<std::pair<int, double>> expected,
                 double tolerance) {
    for (size_t k = 0; k < fit.coefficients.size(); ++k) {
        double want = 0;
        for (const auto& [j, value] : expected)
            if (static_cast<size_t>(j) == k + 1) want = value;
        EXPECT_NEAR(fit.coefficients[k], want, tolerance) << "term " << k + 1;
    }
    EXPECT_LT(fit.residual_rms, tolerance);
}

TEST(Zernike, NollIndicesFollowNollsTable) {
    const int expected[][3] = {{1, 0, 0},  {2, 1, 1},  {3, 1, -1},  {4, 2, 0},  {5, 2, -2},
                               {6, 2, 2},  {7, 3, -1}, {8, 3, 1},   {9, 3, -3}, {10, 3, 3},
                               {11, 4, 0}, {12, 4, 2}, {13, 4, -2}, {14, 4, 4}, {15, 4, -4},
                               {16, 5, 1}, {22, 6, 0}, {37, 8, 0}};
    for (const auto& e : expected) {
        const ZernikeIndex z = zernike_index(ZernikeOrdering::Noll, e[0]);
        EXPECT_EQ(z.n, e[1]) << "Noll " << e[0];
        EXPECT_EQ(z.m, e[2]) << "Noll " << e[0];
    }
}

TEST(Zernike, FringeIndicesFollowTheFringeSet) {
    const int expected[][3] = {{1, 0, 0},   {2, 1, 1},  {3, 1, -1},  {4, 2, 0},  {5, 2, 2},
                               {6, 2, -2},  {7, 3, 1},  {8, 3, -1},  {9, 4, 0},  {10, 3, 3},
                               {11, 3, -3}, {12, 4, 2}, {13, 4, -2}, {14, 5, 1}, {15, 5, -1},
                               {16, 6, 0},  {17, 4, 4}, {25, 8, 0},  {26, 5, 5}, {35, 9, -1},
                               {36, 10, 0}, {37, 12, 0}};
    for (const auto& e : expected) {
        const ZernikeIndex z = zernike_index(ZernikeOrdering::Fringe, e[0]);
        EXPECT_EQ(z.n, e[1]) << "Fringe " << e[0];
        EXPECT_EQ(z.m, e[2]) << "Fringe " << e[0];
    }
    EXPECT_THROW(zernike_index(ZernikeOrdering::Fringe, 38), std::invalid_argument);
    EXPECT_THROW(zernike_index(ZernikeOrdering::Noll, 0), std::invalid_argument);
}

TEST(Zernike, NollTermsHaveUnitMeanSquareAndFringeTermsAreOneAtTheRim) {
    // The mean square over a fine polar grid of the unit disc (midpoint rule in ρ² and θ).
    const int rings = 400, spokes = 720;
    for (int j = 1; j <= 22; ++j) {
        double sum = 0;
        for (int a = 0; a < rings; ++a)
            for (int b = 0; b < spokes; ++b) {
                const double rho = std::sqrt((a + 0.5) / rings),
                             theta = 2 * kPi * (b + 0.5) / spokes;
                const double z = zernike_value(ZernikeOrdering::Noll, j, rho, theta);
                sum += z * z;
            }
        EXPECT_NEAR(sum / (rings * spokes), 1.0, 2e-4) << "Noll " << j;
    }
    for (int j = 1; j <= 37; ++j) {
        const ZernikeIndex z = zernike_index(ZernikeOrdering::Fringe, j);
        // cos(mθ) is 1 at θ = 0, sin(mθ) at θ = π/(2m).
        const double theta = z.m < 0 ? kPi / (2 * -z.m) : 0.0;
        EXPECT_NEAR(zernike_value(ZernikeOrdering::Fringe, j, 1.0, theta), 1.0, 1e-12) << j;
    }
}

TEST(Zernike, PureDefocusIsZ4Only) {
    // W020 = 0.25 waves of ρ².
    const PupilFunction p =
        zernike_test_pupil([](double x, double y) { return 0.25 * (x * x + y * y); });
    expect_only(fit_zernike(p, ZernikeOrdering::Noll, 37),
                {{1, 0.125}, {4, 0.25 / (2 * std::sqrt(3.0))}}, 1e-6);
    expect_only(fit_zernike(p, ZernikeOrdering::Fringe, 37), {{1, 0.125}, {4, 0.125}}, 1e-6);
}

TEST(Zernike, PrimarySphericalIsZ11WithItsBalancingDefocus) {
    const double w040 = 0.8;
    const PupilFunction p = zernike_test_pupil([](double x, double y) {
        const double r2 = x * x + y * y;
        return 0.8 * r2 * r2;
    });
    expect_only(
        fit_zernike(p, ZernikeOrdering::Noll, 37),
        {{1, w040 / 3}, {4, w040 / (2 * std::sqrt(3.0))}, {11, w040 / (6 * std::sqrt(5.0))}}, 1e-6);
    // Fringe: ρ⁴ = Z9/6 + Z4/2 + 1/3.
    expect_only(fit_zernike(p, ZernikeOrdering::Fringe, 37),
                {{1, w040 / 3}, {4, w040 / 2}, {9, w040 / 6}}, 1e-6);
}

TEST(Zernike, ComaAlongYIsZ7WithItsTilt) {
    const PupilFunction p =
        zernike_test_pupil([](double x, double y) { return (x * x + y * y) * y; });
    expect_only(fit_zernike(p, ZernikeOrdering::Noll, 37),
                {{3, 1.0 / 3}, {7, 1.0 / (3 * std::sqrt(8.0))}}, 1e-6);
    expect_only(fit_zernike(p, ZernikeOrdering::Fringe, 37), {{3, 2.0 / 3}, {8, 1.0 / 3}}, 1e-6);
}

TEST(Zernike, AWavefrontBeyondTheTermsLeavesAResidual) {
    // ρ¹⁰ needs Noll terms up to n = 10; four terms leave most of it.
    const PupilFunction p =
        zernike_test_pupil([](double x, double y) { return std::pow(x * x + y * y, 5); });
    EXPECT_GT(fit_zernike(p, ZernikeOrdering::Noll, 4).residual_rms, 0.05);
    EXPECT_LT(fit_zernike(p, ZernikeOrdering::Fringe, 36).residual_rms, 1e-6);
}

TEST(Zernike, TooFewSamplesAreRefused) {
    const PupilFunction p = zernike_test_pupil([](double, double) { return 0.0; }, 4);
    EXPECT_THROW(fit_zernike(p, ZernikeOrdering::Noll, 37), std::invalid_argument);
    EXPECT_THROW(fit_zernike(p, ZernikeOrdering::Noll, 0), std::invalid_argument);
}

}  // namespace
}  // namespace lenslab
