// How materials split light: weights add up, Fresnel shares, thin panes per polarisation.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "optics/fresnel.h"
#include "scene/scattering.h"

namespace lenslab {
namespace {

double total(const Scattering& s) {
    double sum = s.diffuse;
    for (int i = 0; i < s.count; ++i) sum += s.branches[i].weight;
    return sum;
}

TEST(Scattering, GlassSplitsByFresnelAndConservesPower) {
    Material glass;
    glass.transparency = 1;
    glass.index = constant_index(1.5);
    const Scattering s = scatter(glass, true, {0, 0, -1}, {0, 0, 1}, kLineD);
    ASSERT_EQ(s.count, 2);
    EXPECT_EQ(s.branches[0].event, Event::Reflect);
    EXPECT_NEAR(s.branches[0].weight, 0.04, 1e-15);
    EXPECT_EQ(s.branches[1].event, Event::Refract);
    EXPECT_NEAR(total(s), 1.0, 1e-15);
}

TEST(Scattering, MixedMaterialSharesAddUpToOne) {
    Material m;
    m.transparency = 0.5;
    m.specular = 0.3;
    for (double a = 0; a < 89; a += 7) {
        const double r = a * std::numbers::pi / 180;
        const Scattering s = scatter(m, true, {std::sin(r), 0, -std::cos(r)}, {0, 0, 1}, kLineD);
        EXPECT_NEAR(total(s), 1.0, 1e-12) << a;
    }
}

TEST(Scattering, ThinPaneSumsReflectionsPerPolarisation) {
    // Incoherent slab reflectance 2R / (1 + R) for each polarisation (Hecht section 9.7),
    // then averaged: at 60 degrees on n = 1.5, 0.1519 (averaging R first would give 0.1638).
    Material pane;
    pane.transparency = 1;
    pane.index = constant_index(1.5);
    const double a = 60 * std::numbers::pi / 180;
    const Scattering s = scatter(pane, false, {std::sin(a), 0, -std::cos(a)}, {0, 0, 1}, kLineD);
    const FresnelTerms f = fresnel_dielectric(std::cos(a), 1.0, 1.5);
    const double expected = 0.5 * (2 * f.rs / (1 + f.rs) + 2 * f.rp / (1 + f.rp));
    ASSERT_EQ(s.count, 2);
    EXPECT_NEAR(s.branches[0].weight, expected, 1e-15);
    EXPECT_NEAR(s.branches[0].weight, 0.1519, 5e-4);
    EXPECT_NEAR(s.branches[1].direction.x, std::sin(a), 1e-15);  // straight through
    EXPECT_NEAR(total(s), 1.0, 1e-15);
}

TEST(Scattering, TotalInternalReflectionSendsEverythingBack) {
    Material glass;
    glass.transparency = 1;
    const double a = 50 * std::numbers::pi / 180;  // > 41.8 degrees, from inside
    const Scattering s = scatter(glass, true, {std::sin(a), 0, std::cos(a)}, {0, 0, 1}, kLineD);
    ASSERT_EQ(s.count, 1);
    EXPECT_EQ(s.branches[0].event, Event::Tir);
    EXPECT_NEAR(s.branches[0].weight, 1.0, 1e-15);
    EXPECT_LT(s.branches[0].direction.z, 0.0);
}

TEST(Scattering, PickEventTakesEachShareInTurn) {
    // Diffuse 0.1, then the branches' weights 0.3 and 0.5, the last 0.1 absorbed: a uniform
    // number picks the event whose share holds it, so each is taken with its probability.
    Scattering s;
    s.count = 2;
    s.branches[0].weight = 0.3;
    s.branches[1].weight = 0.5;
    EXPECT_TRUE(pick_event(s, 0.1, 0.05).diffuse);
    EXPECT_EQ(pick_event(s, 0.1, 0.15).branch, &s.branches[0]);
    EXPECT_EQ(pick_event(s, 0.1, 0.85).branch, &s.branches[1]);
    const EventPick absorbed = pick_event(s, 0.1, 0.95);
    EXPECT_FALSE(absorbed.diffuse);
    EXPECT_EQ(absorbed.branch, nullptr);
}

TEST(Scattering, DiffuseContinuationFollowsTheBrightestChannel) {
    Scattering s;
    s.diffuse = 0.8;
    Material m;
    m.color = {0.5, 0.25, 0.1};
    EXPECT_DOUBLE_EQ(diffuse_continuation(s, m), 0.4);
    m.color = {0, 0, 0};
    EXPECT_EQ(diffuse_continuation(s, m), 0.0);  // a black surface ends every path
}

}  // namespace
}  // namespace lenslab
