#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "optics/grin_profile.h"

namespace lenslab {
namespace {

// The analytic gradient against a central difference of the index itself.
void expect_gradient_matches_index(const GrinProfile& g, const Vec3& p) {
    const double h = 1e-6;
    const Vec3 grad = g.gradient(p);
    const Vec3 e[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const double numeric[3] = {
        (g.index(p + e[0] * h) - g.index(p - e[0] * h)) / (2 * h),
        (g.index(p + e[1] * h) - g.index(p - e[1] * h)) / (2 * h),
        (g.index(p + e[2] * h) - g.index(p - e[2] * h)) / (2 * h),
    };
    EXPECT_NEAR(grad.x, numeric[0], 1e-8) << grin_kind_name(g.kind);
    EXPECT_NEAR(grad.y, numeric[1], 1e-8) << grin_kind_name(g.kind);
    EXPECT_NEAR(grad.z, numeric[2], 1e-8) << grin_kind_name(g.kind);
}

TEST(GrinProfile, LuneburgIsRootTwoAtTheCentreAndOneAtTheRim) {
    // Luneburg, Mathematical Theory of Optics (1944): n = sqrt(2 - (r/R)^2).
    GrinProfile g;
    g.kind = GrinKind::Luneburg;
    g.radius = 2.0;
    EXPECT_DOUBLE_EQ(g.index({0, 0, 0}), std::sqrt(2.0));
    EXPECT_DOUBLE_EQ(g.index({0, 2, 0}), 1.0);
    EXPECT_DOUBLE_EQ(g.index({1, 0, 0}), std::sqrt(1.75));
}

TEST(GrinProfile, FisheyeHalvesItsIndexAtRadiusR) {
    // Maxwell's fish-eye: n = n0 / (1 + (r/R)^2), so n(R) = n0 / 2.
    GrinProfile g;
    g.kind = GrinKind::Fisheye;
    g.n0 = 2.0;
    g.radius = 3.0;
    EXPECT_DOUBLE_EQ(g.index({0, 0, 3}), 1.0);
    EXPECT_DOUBLE_EQ(g.index({0, 0, 0}), 2.0);
}

TEST(GrinProfile, RadialDependsOnlyOnTheDistanceFromTheAxis) {
    GrinProfile g;
    g.kind = GrinKind::Radial;
    g.n0 = 1.6;
    g.A = 0.5;
    g.axis = normalize(Vec3{1, 1, 0});
    // A point on the axis, then one at distance 1 from it: n0 (1 - A/2).
    EXPECT_DOUBLE_EQ(g.index({3, 3, 0}), 1.6);
    EXPECT_NEAR(g.index(Vec3{3, 3, 0} + Vec3{0, 0, 1}), 1.6 * 0.75, 1e-15);
}

TEST(GrinProfile, AnalyticGradientsAreTheIndexSlope) {
    GrinProfile lune;
    lune.kind = GrinKind::Luneburg;
    lune.radius = 1.5;
    GrinProfile fish;
    fish.kind = GrinKind::Fisheye;
    fish.n0 = 2;
    fish.radius = 0.7;
    GrinProfile radial;
    radial.kind = GrinKind::Radial;
    radial.n0 = 1.5;
    radial.A = 0.3;
    radial.axis = normalize(Vec3{0.2, -0.4, 1});
    GrinProfile axial;
    axial.kind = GrinKind::Axial;
    axial.n0 = 1.4;
    axial.A = 0.05;
    axial.axis = normalize(Vec3{0, 1, 1});
    for (const GrinProfile* g : {&lune, &fish, &radial, &axial}) {
        for (const Vec3& p : {Vec3{0.1, 0.2, 0.3}, Vec3{-0.5, 0.4, 0.2}, Vec3{0.3, -0.6, -0.7}})
            expect_gradient_matches_index(*g, p);
    }
}

TEST(GrinProfile, FormulaGradientIsNumericalAndZeroWhenUniform) {
    GrinProfile g;
    g.kind = GrinKind::Formula;
    g.formula = std::make_shared<Formula>("1.5 + 0.1*x*x - 0.2*y*z",
                                          std::vector<std::string>{"x", "y", "z"}, "");
    const Vec3 p{0.3, -0.2, 0.5};
    EXPECT_DOUBLE_EQ(g.index(p), 1.5 + 0.1 * 0.09 + 0.2 * 0.1);
    const Vec3 grad = g.gradient(p);
    EXPECT_NEAR(grad.x, 0.2 * 0.3, 1e-9);
    EXPECT_NEAR(grad.y, -0.2 * 0.5, 1e-9);
    EXPECT_NEAR(grad.z, -0.2 * -0.2, 1e-9);
    GrinProfile uniform = g;
    uniform.formula = std::make_shared<Formula>("1.5", std::vector<std::string>{"x", "y", "z"}, "");
    const Vec3 zero = uniform.gradient(p);
    EXPECT_EQ(zero.x, 0.0);
    EXPECT_EQ(zero.y, 0.0);
    EXPECT_EQ(zero.z, 0.0);
}

}  // namespace
}  // namespace lenslab
