// Fresnel equations against textbook values (Hecht, Optics, 5th ed., sections 4.6.2-4.7).

#include <gtest/gtest.h>

#include <cmath>

#include "math/constants.h"
#include "optics/fresnel.h"

namespace lenslab {
namespace {

double deg(double d) { return d * kPi / 180.0; }

TEST(Fresnel, NormalIncidenceOnGlassReflectsFourPercent) {
    // R = ((n2 - n1) / (n2 + n1))^2 = (0.5 / 2.5)^2 = 0.04 for n = 1.5 (Hecht eq. 4.67).
    const FresnelTerms f = fresnel_dielectric(1.0, 1.0, 1.5);
    EXPECT_NEAR(f.reflectance(), 0.04, 1e-15);
    EXPECT_NEAR(f.rs, 0.04, 1e-15);
    EXPECT_NEAR(f.rp, 0.04, 1e-15);
    EXPECT_NEAR(f.transmittance(), 0.96, 1e-15);
    // The same from inside the glass: the interface is reciprocal.
    EXPECT_NEAR(fresnel_dielectric(1.0, 1.5, 1.0).reflectance(), 0.04, 1e-15);
}

TEST(Fresnel, BrewsterAngleExtinguishesP) {
    // tan(theta_B) = n2 / n1 (Hecht eq. 8.21).
    const double theta_b = std::atan(1.5);
    const FresnelTerms f = fresnel_dielectric(std::cos(theta_b), 1.0, 1.5);
    EXPECT_NEAR(f.rp, 0.0, 1e-15);
    EXPECT_GT(f.rs, 0.1);
    // Inside the glass, Brewster's angle is atan(1 / 1.5).
    EXPECT_NEAR(fresnel_dielectric(std::cos(std::atan(1.0 / 1.5)), 1.5, 1.0).rp, 0.0, 1e-15);
}

TEST(Fresnel, TotalInternalReflectionBeyondCriticalAngle) {
    // sin(theta_c) = n2 / n1 = 1 / 1.5, theta_c = 41.81 degrees (Hecht section 4.7).
    const double theta_c = std::asin(1.0 / 1.5);
    EXPECT_NEAR(theta_c, deg(41.8103149), 1e-8);
    for (double extra : {1e-6, 0.01, 0.3, 0.8}) {
        const FresnelTerms f = fresnel_dielectric(std::cos(theta_c + extra), 1.5, 1.0);
        EXPECT_TRUE(f.total_internal_reflection);
        EXPECT_EQ(f.reflectance(), 1.0);
    }
    const FresnelTerms below = fresnel_dielectric(std::cos(theta_c - 1e-3), 1.5, 1.0);
    EXPECT_FALSE(below.total_internal_reflection);
    EXPECT_LT(below.reflectance(), 1.0);
    EXPECT_GT(below.reflectance(), 0.5);  // R rises steeply towards 1 just below theta_c
}

TEST(Fresnel, FortyFiveDegreesMatchesClosedForm) {
    // Hecht eqs. 4.42-4.43: rs = -sin(i - t) / sin(i + t), rp = tan(i - t) / tan(i + t).
    const double i = deg(45.0);
    const double t = std::asin(std::sin(i) / 1.5);
    const double rs = -std::sin(i - t) / std::sin(i + t);
    const double rp = std::tan(i - t) / std::tan(i + t);
    const FresnelTerms f = fresnel_dielectric(std::cos(i), 1.0, 1.5);
    EXPECT_NEAR(f.rs, rs * rs, 1e-14);
    EXPECT_NEAR(f.rp, rp * rp, 1e-14);
    // The same as printed values: Rs = 0.0920, Rp = 0.00847 (= Rs^2, a known
    // identity at 45 degrees: Rp = Rs^2).
    EXPECT_NEAR(f.rs, 0.09201, 1e-5);
    EXPECT_NEAR(f.rp, 0.008466, 1e-5);
    EXPECT_NEAR(f.rp, f.rs * f.rs, 1e-14);
}

TEST(Fresnel, EnergyIsConservedAndReciprocal) {
    for (double a = 0.0; a < 89.9; a += 0.5) {
        const double ci = std::cos(deg(a));
        const FresnelTerms out = fresnel_dielectric(ci, 1.0, 1.5);
        EXPECT_NEAR(out.reflectance() + out.transmittance(), 1.0, 1e-15);
        EXPECT_GE(out.rs, out.rp - 1e-15);  // s always reflects at least as much as p
        // Reciprocity: the refracted ray travelling back sees the same reflectance.
        const double st = std::sin(deg(a)) / 1.5;
        const FresnelTerms back = fresnel_dielectric(std::sqrt(1.0 - st * st), 1.5, 1.0);
        EXPECT_NEAR(back.reflectance(), out.reflectance(), 1e-12);
    }
    // Grazing incidence reflects everything.
    EXPECT_NEAR(fresnel_dielectric(0.0, 1.0, 1.5).reflectance(), 1.0, 1e-15);
}

}  // namespace
}  // namespace lenslab
