// A line laser's fan and a beam through a slit (light.h) against closed forms: the fan's
// irradiance P / (theta rho 2 r) in its sheet and nothing outside it; the slit's P / A with A
// the disc's area inside the strip, 2 [h sqrt(r^2 - h^2) + r^2 asin(h / r)]; the chords their
// in-scattering is sampled along, worked out by hand for rays across them; and the slit's
// aimed and fallback photons carrying, on average, the share of the flux they stand for.

#include <gtest/gtest.h>

#include <cmath>

#include "math/constants.h"
#include "scene/light_source.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

// The disc of radius r inside the strip |x| <= h: the disc less its two segments beyond h.
double disc_in_strip(double r, double h) {
    return 2 * (h * std::sqrt(r * r - h * h) + r * r * std::asin(h / r));
}

Scene one_light_scene(const std::string& light) {
    return parse_scene(R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
        "lights": [)" + light +
                       "]}");
}

// The interval a light samples along `ray`: t at u = 0, and its length 1 / pdf.
struct Chord {
    double t0 = 0, t1 = 0;
};
Chord sampled_chord(const Light& light, const Ray& ray, double t_max) {
    double t, pdf;
    EXPECT_TRUE(light.sample_in_scattering(ray, t_max, 0.0, t, pdf));
    return {t, t + 1 / pdf};
}

// A 60-degree fan of a laser along +x: its sheet is the horizontal plane y = 0, 2 r = 0.02
// thick, spreading along z (the default axis, square to +x and +y).
const char* kFan =
    R"({"type": "laser", "position": [0, 0, 0], "direction": [1, 0, 0], "radius": 0.01,
        "power": 2, "wavelength": 532, "fan_angle": 60})";

TEST(BeamShapes, FanIrradianceIsPowerOverThetaRhoThickness) {
    const Scene scene = one_light_scene(kFan);
    const Light& fan = *scene.lights().at(0);
    EXPECT_NEAR(fan.power(), 2, 1e-9);
    EXPECT_TRUE(fan.is_delta());
    Rng rng(5, 1);
    LightSample s;
    const double theta = kPi / 3, phi = 20 * kPi / 180, rho = 3;
    const Vec3 p{rho * std::cos(phi), 0.004, rho * std::sin(phi)};
    ASSERT_TRUE(fan.sample_li(p, rng, s));
    EXPECT_NEAR(s.factor, 1 / (theta * rho * 0.02), 1e-12);
    EXPECT_NEAR(s.distance, rho, 1e-12);
    EXPECT_NEAR(s.wi.x, -std::cos(phi), 1e-12);
    EXPECT_NEAR(s.wi.y, 0, 1e-12);
    EXPECT_NEAR(s.wi.z, -std::sin(phi), 1e-12);
    // Above the sheet, beyond its edge at 30 degrees either side, behind the aperture.
    EXPECT_FALSE(fan.sample_li({3, 0.011, 0}, rng, s));
    EXPECT_FALSE(fan.sample_li({3 * std::cos(0.55), 0, 3 * std::sin(0.55)}, rng, s));
    EXPECT_FALSE(fan.sample_li({3 * std::cos(0.55), 0, -3 * std::sin(0.55)}, rng, s));
    EXPECT_TRUE(fan.sample_li({3 * std::cos(0.5), 0, -3 * std::sin(0.5)}, rng, s));
    EXPECT_FALSE(fan.sample_li({-1, 0, 0}, rng, s));
}

TEST(BeamShapes, FanAxisAndVerticalBeamsTurnTheSheet) {
    // fan_axis [0, 1, 1] across a beam along +x spreads along y + z: the sheet's normal is
    // (0, 1, -1) / sqrt 2.
    const Scene tilted = one_light_scene(
        R"({"type": "beam", "origin": [0, 0, 0], "direction": [1, 0, 0], "radius": 0.01,
            "power": 1, "fan_angle": 90, "fan_axis": [0, 1, 1]})");
    Rng rng(6, 1);
    LightSample s;
    EXPECT_TRUE(tilted.lights()[0]->sample_li({1, 0.5, 0.5}, rng, s));
    EXPECT_FALSE(tilted.lights()[0]->sample_li({1, 0, 0.5}, rng, s));
    // A vertical beam's fan spreads along x by default.
    const Scene down = one_light_scene(
        R"({"type": "laser", "position": [0, 2, 0], "direction": [0, -1, 0], "radius": 0.01,
            "power": 1, "fan_angle": 40})");
    EXPECT_TRUE(down.lights()[0]->sample_li({0.5, 0, 0}, rng, s));
    EXPECT_FALSE(down.lights()[0]->sample_li({0, 0, 0.5}, rng, s));
}

TEST(BeamShapes, FanPhotonsLeaveTheApertureInsideTheSheet) {
    const Scene scene = one_light_scene(kFan);
    const Light& fan = *scene.lights()[0];
    Rng rng(7, 1);
    double widest = 0;
    for (int i = 0; i < 10000; ++i) {
        const PhotonStart ph = fan.sample_le(rng);
        EXPECT_EQ(ph.scale, 1.0);
        EXPECT_LE(std::abs(ph.ray.origin.y), 0.01);
        EXPECT_EQ(ph.ray.origin.x, 0.0);
        EXPECT_NEAR(ph.ray.direction.y, 0, 1e-15);
        const double phi = std::atan2(ph.ray.direction.z, ph.ray.direction.x);
        EXPECT_LE(std::abs(phi), kPi / 6 + 1e-12);
        widest = std::max(widest, std::abs(phi));
    }
    EXPECT_GT(widest, 0.99 * kPi / 6);
    EXPECT_FALSE(fan.worth_aiming(PhotonTargets({{{3, 0, 0}, 0.1}})));
}

// Rays across the sheet: the chord sampled is the one the slab and the wedge cut, and
// every point on it is lit.
TEST(BeamShapes, FanInScatteringChordHoldsTheSheet) {
    const Scene scene = one_light_scene(kFan);
    const Light& fan = *scene.lights()[0];
    Rng rng(8, 1);
    LightSample s;
    // Straight down through the sheet at (2, 0, 0.3): the slab |y| <= 0.01.
    const Ray down{{2, 1, 0.3}, {0, -1, 0}};
    Chord c = sampled_chord(fan, down, 10);
    EXPECT_NEAR(c.t0, 0.99, 1e-12);
    EXPECT_NEAR(c.t1, 1.01, 1e-12);
    // Slanting at 45 degrees: 0.02 sqrt 2 long.
    const Ray slant{{2, 1, 0.3 - 1}, normalize(Vec3{0, -1, 1})};
    c = sampled_chord(fan, slant, 10);
    EXPECT_NEAR(c.t0, 0.99 * std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(c.t1, 1.01 * std::sqrt(2.0), 1e-12);
    // Within the sheet, across the fan at x = 2: |z| <= 2 tan 30 degrees.
    const Ray across{{2, 0, -5}, {0, 0, 1}};
    const double half = 2 * std::tan(kPi / 6);
    c = sampled_chord(fan, across, 100);
    EXPECT_NEAR(c.t0, 5 - half, 1e-12);
    EXPECT_NEAR(c.t1, 5 + half, 1e-12);
    for (double u = 0.01; u < 1; u += 0.1) {
        double t, pdf;
        ASSERT_TRUE(fan.sample_in_scattering(across, 100, u, t, pdf));
        EXPECT_NEAR(pdf, 1 / (2 * half), 1e-12);
        EXPECT_TRUE(fan.sample_li(across.at(t), rng, s)) << t;
    }
    EXPECT_FALSE(fan.sample_li(across.at(c.t0 - 1e-6), rng, s));
    EXPECT_FALSE(fan.sample_li(across.at(c.t1 + 1e-6), rng, s));
    // t_max cuts the chord; a ray beside the sheet or behind the aperture has none.
    c = sampled_chord(fan, across, 5);
    EXPECT_NEAR(c.t1, 5, 1e-12);
    double t, pdf;
    EXPECT_FALSE(fan.sample_in_scattering({{2, 0.02, -5}, {0, 0, 1}}, 100, 0.5, t, pdf));
    EXPECT_FALSE(fan.sample_in_scattering({{-1, 1, 0}, {0, -1, 0}}, 100, 0.5, t, pdf));
}

// A white beam of radius 0.5 along +z through a slit 0.4 wide standing upright: the strip
// |x| <= 0.2.
const char* kSlit =
    R"({"type": "beam", "origin": [0, 0, -2], "direction": [0, 0, 1], "radius": 0.5,
        "power": 3, "slit_width": 0.4})";

TEST(BeamShapes, SlitIrradianceIsPowerOverTheOpenArea) {
    const Scene scene = one_light_scene(kSlit);
    const Light& slit = *scene.lights().at(0);
    EXPECT_NEAR(slit.power(), 3, 1e-9);
    Rng rng(9, 1);
    LightSample s;
    ASSERT_TRUE(slit.sample_li({0.1, 0.3, 0}, rng, s));
    EXPECT_NEAR(s.factor, 1 / disc_in_strip(0.5, 0.2), 1e-12);
    EXPECT_NEAR(s.distance, 2, 1e-12);
    EXPECT_FALSE(slit.sample_li({0.3, 0, 0}, rng, s));     // in the disc, off the strip
    EXPECT_FALSE(slit.sample_li({0.1, 0.49, 0}, rng, s));  // in the strip, off the disc
    EXPECT_FALSE(slit.sample_li({0, 0, -3}, rng, s));      // behind
    // A slit as wide as the beam is no slit: pi r^2.
    const Scene open = one_light_scene(
        R"({"type": "beam", "origin": [0, 0, -2], "direction": [0, 0, 1], "radius": 0.5,
            "power": 3, "slit_width": 1})");
    ASSERT_TRUE(open.lights()[0]->sample_li({0.3, 0, 0}, rng, s));
    EXPECT_NEAR(s.factor, 1 / (kPi * 0.25), 1e-12);
    // slit_axis [1, 0, 0] turns the strip to |y| <= 0.2.
    const Scene turned = one_light_scene(
        R"({"type": "beam", "origin": [0, 0, -2], "direction": [0, 0, 1], "radius": 0.5,
            "power": 3, "slit_width": 0.4, "slit_axis": [1, 0, 0]})");
    EXPECT_TRUE(turned.lights()[0]->sample_li({0.3, 0.1, 0}, rng, s));
    EXPECT_FALSE(turned.lights()[0]->sample_li({0.1, 0.3, 0}, rng, s));
}

TEST(BeamShapes, SlitInScatteringChordIsCutByTheStrip) {
    const Scene scene = one_light_scene(kSlit);
    const Light& slit = *scene.lights()[0];
    // Along x through the axis: the cylinder gives [2.5, 3.5], the strip [2.8, 3.2].
    Chord c = sampled_chord(slit, {{-3, 0, 0}, {1, 0, 0}}, 100);
    EXPECT_NEAR(c.t0, 2.8, 1e-12);
    EXPECT_NEAR(c.t1, 3.2, 1e-12);
    // Along y at x = 0.1, inside the strip: the cylinder's chord, |y| <= sqrt(0.25 - 0.01).
    const double half = std::sqrt(0.24);
    c = sampled_chord(slit, {{0.1, -3, 0}, {0, 1, 0}}, 100);
    EXPECT_NEAR(c.t0, 3 - half, 1e-12);
    EXPECT_NEAR(c.t1, 3 + half, 1e-12);
    // Along y at x = 0.3: in the cylinder but beside the slit.
    double t, pdf;
    EXPECT_FALSE(slit.sample_in_scattering({{0.3, -3, 0}, {0, 1, 0}}, 100, 0.5, t, pdf));
}

// Photons: all in the open area; with no targets sample_le_towards takes the strip's
// rectangle and weights by rect / A inside the disc (mean 1); aimed at a sphere of radius 0.3
// on the axis, the mean scale is the open part of its disc over A. N = 100000 each; the
// relative sigmas are 0.05% and 0.17%, the tolerances about 5 sigma.
TEST(BeamShapes, SlitPhotonsCarryTheFluxOfTheOpenArea) {
    const Scene scene = one_light_scene(kSlit);
    const Light& slit = *scene.lights()[0];
    const double area = disc_in_strip(0.5, 0.2);
    Rng rng(10, 1);
    constexpr int kN = 100000;
    int central = 0;
    for (int i = 0; i < kN; ++i) {
        const PhotonStart ph = slit.sample_le(rng);
        ASSERT_EQ(ph.scale, 1.0);
        const Vec3& o = ph.ray.origin;
        ASSERT_LE(std::abs(o.x), 0.2);
        ASSERT_LE(o.x * o.x + o.y * o.y, 0.25 + 1e-12);
        ASSERT_NEAR(o.z, -2, 1e-12);
        if (std::abs(o.x) <= 0.1) ++central;
    }
    // The central strip |x| <= 0.1 holds disc_in_strip(r, 0.1) / A of them: p = 0.52,
    // sigma = sqrt(p (1 - p) / N) = 0.0016.
    EXPECT_NEAR(double(central) / kN, disc_in_strip(0.5, 0.1) / area, 0.008);

    double fallback = 0, aimed = 0;
    const PhotonTargets none;
    const PhotonTargets sphere({{{0, 0, 1}, 0.3}});
    EXPECT_TRUE(slit.worth_aiming(sphere));
    EXPECT_FALSE(slit.worth_aiming(PhotonTargets({{{0, 0, 1}, 0.4}})));
    for (int i = 0; i < kN; ++i) {
        AimSample u;
        for (double& x : u) x = rng.uniform();
        fallback += slit.sample_le_towards(none, u).scale;
        aimed += slit.sample_le_towards(sphere, u).scale;
    }
    EXPECT_NEAR(fallback / kN, 1, 0.003);
    const double expected = disc_in_strip(0.3, 0.2) / area;
    EXPECT_NEAR(aimed / kN, expected, 0.008 * expected);
}

}  // namespace
}  // namespace lenslab
