// The Light interface against closed forms: each light's power, the irradiance its
// sample_li gives (inverse square and cosine for a point, P / (pi r^2) across a beam, the
// irradiance under a glowing sphere), that photons are shared among lights by power, and
// that the light sampler's choice is unbiased.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "render/photon_emission.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

constexpr double kPi = std::numbers::pi;

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
