// The Light interface against closed forms: each light's power, the irradiance its
// sample_li gives (inverse square and cosine for a point, P / (pi r^2) across a beam, the
// irradiance under a glowing sphere), that photons are shared among lights by power, and
// that the light sampler's choice is unbiased.

#include <gtest/gtest.h>

#include <cmath>

#include "math/constants.h"
#include "render/photon_emission.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

Scene lights_scene(const std::string& lights) {
    return parse_scene(R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
        "materials": {"lamp": {"color": 0, "emission": {"intensity": 2}}},
        "objects": [{"type": "sphere", "center": [0, 3, 0], "radius": 0.5, "material": "lamp"}],
        "lights": [)" + lights +
                       "]}");
}

TEST(LightSource, PowerAndIrradianceMatchTheClosedForms) {
    const Scene scene = lights_scene(R"({"type": "point", "position": [0, 2, 0], "power": 3},
        {"type": "beam", "origin": [0, 0, -2], "direction": [0, 0, 1], "radius": 0.5, "power": 5})");
    ASSERT_EQ(scene.lights().size(), 3u);
    const Light& sphere = *scene.lights()[0];
    const Light& point = *scene.lights()[1];
    const Light& beam = *scene.lights()[2];
    // A Lambertian sphere of radiance L sends pi L 4 pi R^2; `power` of the others is theirs.
    EXPECT_NEAR(sphere.power(), kPi * 4 * kPi * 0.25 * 2, 1e-6 * sphere.power());
    EXPECT_NEAR(point.power(), 3, 1e-9);
    EXPECT_NEAR(beam.power(), 5, 1e-9);

    Rng rng(1, 1);
    LightSample s;
    // Point: E = P cos / (4 pi d^2), d = 2, here per unit of the spectrum.
    ASSERT_TRUE(point.sample_li({0, 0, 0}, rng, s));
    EXPECT_NEAR(s.distance, 2, 1e-12);
    EXPECT_NEAR(s.factor, 1 / (4 * kPi * 4), 1e-15);
    EXPECT_NEAR(s.wi.y, 1, 1e-12);
    // Beam: 1 / (pi r^2) inside it, nothing outside or behind.
    ASSERT_TRUE(beam.sample_li({0.2, 0, 1}, rng, s));
    EXPECT_NEAR(s.factor, 1 / (kPi * 0.25), 1e-12);
    EXPECT_NEAR(s.distance, 3, 1e-12);
    EXPECT_FALSE(beam.sample_li({0.6, 0, 1}, rng, s));
    EXPECT_FALSE(beam.sample_li({0, 0, -3}, rng, s));
    // Glowing sphere seen from a point on its axis, facing it: E = pi L (R / d)^2 (a
    // Lambertian sphere looks like a disc of the same radiance); the estimate's mean.
    double sum = 0;
    constexpr int kSamples = 200000;
    for (int i = 0; i < kSamples; ++i) {
        if (sphere.sample_li({0, 0, 0}, rng, s)) sum += s.factor * s.wi.y;
    }
    const double expected = kPi * (0.5 / 3) * (0.5 / 3);
    EXPECT_NEAR(sum / kSamples, expected, 0.002 * expected);
    EXPECT_FALSE(sphere.sample_li({0, 3.1, 0}, rng, s));  // inside
}

// A spot light's cone: E = Phi / (2 pi (1 - cos theta0) r^2) on the axis of a hard-edged
// one, the smoothstep's half-way value half-way through a soft edge, nothing outside; and its
// photons carry Phi between them, which holds only if the intensity's normalisation (the
// smoothstep integrating to half its interval in the cosine) is right.
TEST(LightSource, SpotLightFillsItsConeWithItsPower) {
    const Scene scene = lights_scene(
        R"({"type": "spot", "position": [0, 2, 0], "direction": [0, -1, 0], "cone_angle": 30, "power": 3},
        {"type": "spot", "position": [0, 2, 0], "direction": [0, -1, 0], "cone_angle": 40,
         "falloff": 20, "power": 3})");
    ASSERT_EQ(scene.lights().size(), 3u);
    const Light& hard = *scene.lights()[1];
    const Light& soft = *scene.lights()[2];
    EXPECT_NEAR(hard.power(), 3, 1e-9);

    Rng rng(3, 1);
    LightSample s;
    const double cos30 = std::cos(kPi / 6);
    ASSERT_TRUE(hard.sample_li({0, 0, 0}, rng, s));
    EXPECT_NEAR(s.distance, 2, 1e-12);
    EXPECT_NEAR(s.factor, 1 / (2 * kPi * (1 - cos30) * 4), 1e-12);
    // 2 tan 29.9 degrees from the axis is inside, 2 tan 30.1 outside.
    EXPECT_TRUE(hard.sample_li({2 * std::tan(29.9 * kPi / 180), 0, 0}, rng, s));
    EXPECT_FALSE(hard.sample_li({2 * std::tan(30.1 * kPi / 180), 0, 0}, rng, s));
    EXPECT_FALSE(hard.sample_li({0, 3, 0}, rng, s));  // behind it

    // The soft edge runs from 20 to 40 degrees; at the cosine half-way between, the
    // smoothstep is 1/2.
    const double cos20 = std::cos(kPi / 9), cos40 = std::cos(2 * kPi / 9);
    const double axis_intensity = 1 / (2 * kPi * ((1 - cos20) + (cos20 - cos40) / 2));
    ASSERT_TRUE(soft.sample_li({0, 1, 0}, rng, s));
    EXPECT_NEAR(s.factor, axis_intensity, 1e-12);
    const double mid = std::acos(0.5 * (cos20 + cos40));
    ASSERT_TRUE(soft.sample_li({std::sin(mid), 2 - std::cos(mid), 0}, rng, s));
    EXPECT_NEAR(s.factor, 0.5 * axis_intensity, 1e-9);

    // Photons: on average each carries the whole flux (scale 1).
    for (const Light* light : {&hard, &soft}) {
        double sum = 0;
        constexpr int kPhotons = 200000;
        for (int i = 0; i < kPhotons; ++i) {
            const PhotonStart p = light->sample_le(rng);
            EXPECT_LE(std::acos(-p.ray.direction.y), (light == &hard ? 30 : 40) * kPi / 180 + 1e-9);
            sum += p.scale;
        }
        EXPECT_NEAR(sum / kPhotons, 1.0, 3e-3);
    }
}

// A laser is a beam of one line: the same spectrum as the beam written out in full.
TEST(LightSource, LaserIsABeamOfOneLine) {
    const Scene scene = lights_scene(
        R"({"type": "laser", "position": [0, 0, -2], "direction": [0, 0, 1], "radius": 0.01,
            "power": 2, "wavelength": 632.8},
        {"type": "beam", "origin": [0, 0, -2], "direction": [0, 0, 1], "radius": 0.01,
            "power": 2, "spectrum": {"line": 632.8, "width": 0.1}})");
    ASSERT_EQ(scene.beams.size(), 2u);
    const Spectrum& laser = *scene.beams[0].spectrum;
    const Spectrum& beam = *scene.beams[1].spectrum;
    for (double nm = 630; nm <= 636; nm += 0.05) EXPECT_EQ(laser.eval(nm), beam.eval(nm)) << nm;
    EXPECT_EQ(laser.eval(600), 0.0);
    EXPECT_NEAR(scene.lights()[1]->power(), 2, 1e-9);
}

TEST(LightSource, PhotonsAreSharedByPower) {
    // The glowing sphere sends pi L 4 pi R^2 = 19.7 W; the points 10 W and 30 W.
    const Scene scene = lights_scene(R"({"type": "point", "position": [0, 2, 0], "power": 10},
        {"type": "point", "position": [1, 2, 0], "power": 30})");
    const std::vector<int64_t> counts = photons_by_power(scene, 1000);
    ASSERT_EQ(counts.size(), 3u);
    const double total = scene.lights()[0]->power() + 40;
    EXPECT_EQ(counts[0] + counts[1] + counts[2], 3000);
    EXPECT_NEAR(counts[1], 3000 * 10 / total, 1);
    EXPECT_NEAR(counts[2], 3000 * 30 / total, 1);
    // So every photon carries about the same power.
    EXPECT_NEAR(scene.lights()[1]->power() / counts[1], scene.lights()[2]->power() / counts[2],
                1e-3);

    // A 1 W beam beside a 300 kW lamp still gets a quarter of an equal share.
    const Scene lopsided =
        lights_scene(R"({"type": "point", "position": [0, 2, 0], "power": 300000},
        {"type": "beam", "origin": [0, 0, -2], "direction": [0, 0, 1], "radius": 0.5, "power": 1})");
    const std::vector<int64_t> c = photons_by_power(lopsided, 1000);
    EXPECT_NEAR(c[2], 3000 * 0.25 / 3 / (1 + 0.25 / 3 + 0.25 / 3), 1);
}

TEST(LightSampler, AsksEveryLightOfASmallSceneAndPicksByPowerInALargeOne) {
    std::string lights;
    for (int i = 0; i < 12; ++i) {
        lights += std::string(i ? ", " : "") +
                  R"({"type": "point", "position": [0, 2, 0], "power": )" + std::to_string(i + 1) +
                  "}";
    }
    const Scene many = lights_scene(lights);
    ASSERT_GT(many.lights().size(), LightSampler::kAskAllUpTo);
    // The sum of power x weight over the lights asked is, on average, the total power.
    Rng rng(5, 5);
    double sum = 0, total = 0;
    for (const LightPtr& l : many.lights()) total += l->power();
    constexpr int kDraws = 20000;
    for (int i = 0; i < kDraws; ++i) {
        many.light_sampler().for_each(
            rng, [&](const Light& l, double weight) { sum += l.power() * weight; });
    }
    // Power sampling makes power x weight the same for every light: no variance at all.
    EXPECT_NEAR(sum / kDraws, total, 1e-9 * total);

    const Scene few = lights_scene(R"({"type": "point", "position": [0, 2, 0], "power": 1})");
    int asked = 0;
    few.light_sampler().for_each(rng, [&](const Light&, double weight) {
        EXPECT_EQ(weight, 1.0);
        ++asked;
    });
    EXPECT_EQ(asked, 2);
}

}  // namespace
}  // namespace lenslab
