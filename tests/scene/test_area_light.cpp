// The rectangle and disc lights against closed forms: the irradiance under a disc light is
// pi L times the configuration factor of a disc seen from a parallel element (Howell, "A
// Catalog of Radiation Heat Transfer Configuration Factors", B-13), its soft shadow behind
// a coaxial opaque disc is the light's factor less that of the occluder's projection (umbra,
// antumbra and fully lit ranges, where the difference is exact), and the share of its
// photons landing on a coaxial disc below is the disc-to-disc factor (Howell C-41). Every
// integrator renders a floor under it, and the unbiased two agree.

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "math/constants.h"
#include "render/render_session.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

// Configuration factor from an element at height h below a parallel disc of radius r whose
// centre is `rho` off the element's normal (Howell B-13).
double element_to_disc(double r, double rho, double h) {
    const double a = h * h + rho * rho;
    return 0.5 *
           (1.0 - (a - r * r) / std::sqrt((a + r * r) * (a + r * r) - 4.0 * r * r * rho * rho));
}

// Disc of radius r1 to a coaxial parallel disc of radius r2 at distance h (Howell C-41).
double disc_to_disc(double r1, double r2, double h) {
    const double R1 = r1 / h, R2 = r2 / h;
    const double x = 1.0 + (1.0 + R2 * R2) / (R1 * R1);
    return 0.5 * (x - std::sqrt(x * x - 4.0 * (R2 / R1) * (R2 / R1)));
}

constexpr double kPower = 10, kRadius = 0.5, kHeight = 2;

// A disc light at height 2 facing down; an opaque disc of radius `occluder` at height 1
// (none when 0).
Scene disc_light_scene(double occluder) {
    std::string objects = "[]";
    if (occluder > 0) {
        objects = R"([{"type": "disc", "center": [0, 1, 0], "normal": [0, 1, 0], "radius": )" +
                  std::to_string(occluder) + R"(, "material": {"color": 0}}])";
    }
    return parse_scene(R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
        "objects": )" + objects +
                       R"(,
        "lights": [{"type": "disc_light", "center": [0, 2, 0], "normal": [0, -1, 0],
                    "radius": 0.5, "power": 10}]})");
}

// Irradiance per unit of the flux spectrum at (rho, 0, 0) on the floor, facing up: the mean
// of shadow-ray samples, as the integrators take them.
double floor_irradiance(const Scene& scene, double rho, int samples) {
    const Light& light = *scene.lights().at(0);
    const Vec3 p{rho, 0, 0};
    Rng rng(7, 3);
    double sum = 0;
    for (int i = 0; i < samples; ++i) {
        LightSample s;
        if (!light.sample_li(p, rng, s)) continue;
        if (scene.occluded({p, s.wi}, 1e-9, s.distance * (1 - 1e-9))) continue;
        sum += s.factor * s.wi.y;
    }
    return sum / samples;
}

// pi L F per unit of flux, L = 1 / (pi A) the light's radiance: F / A, for the light's disc
// or any disc of its plane that glows as it does.
double closed_form(double r, double rho, double h) {
    return element_to_disc(r, rho, h) / (kPi * kRadius * kRadius);
}

TEST(AreaLight, DiscIrradianceFollowsTheConfigurationFactor) {
    const Scene scene = disc_light_scene(0);
    ASSERT_EQ(scene.lights().size(), 1u);
    EXPECT_NEAR(scene.lights()[0]->power(), kPower, 1e-9);
    EXPECT_FALSE(scene.lights()[0]->is_delta());
    // On the axis, under the rim and beyond it: E = Phi F / A.
    for (double rho : {0.0, 0.5, 1.5}) {
        SCOPED_TRACE(rho);
        const double expected = closed_form(kRadius, rho, kHeight);
        EXPECT_NEAR(floor_irradiance(scene, rho, 200000), expected, 0.01 * expected);
    }
    // The back of the light sends nothing.
    LightSample s;
    Rng rng(1, 1);
    EXPECT_FALSE(scene.lights()[0]->sample_li({0, 3, 0}, rng, s));
}

// Seen from a floor point at rho, the occluder (radius a at height 1, half the light's) hides
// the disc of radius 2a centred 2 rho from the point's foot on the light's plane, rho from the
// light's centre.
TEST(AreaLight, DiscLightPenumbraMatchesTheClosedForm) {
    {
        SCOPED_TRACE("occluder's shadow of the light larger than it: umbra and penumbra");
        const double a = 0.4;  // projection radius 0.8 > 0.5
        const Scene scene = disc_light_scene(a);
        // Umbra while the projection covers the light: rho + 0.5 <= 0.8.
        for (double rho : {0.0, 0.25}) EXPECT_EQ(floor_irradiance(scene, rho, 20000), 0.0);
        // Fully lit once it misses the light: rho >= 0.8 + 0.5.
        for (double rho : {1.35, 2.0}) {
            const double expected = closed_form(kRadius, rho, kHeight);
            EXPECT_NEAR(floor_irradiance(scene, rho, 200000), expected, 0.01 * expected);
        }
        // In between, the share of the unshadowed light that arrives rises steadily from
        // nothing to all of it (the light itself falls off outwards, so E alone need not).
        double before = 0;
        for (double rho : {0.4, 0.6, 0.8, 1.0, 1.2}) {
            const double share =
                floor_irradiance(scene, rho, 100000) / closed_form(kRadius, rho, kHeight);
            EXPECT_GT(share, before) << rho;
            EXPECT_LT(share, 1.0) << rho;
            before = share;
        }
    }
    {
        SCOPED_TRACE("smaller: an antumbra, exact while the projection lies inside the light");
        const double a = 0.15;  // projection radius 0.3; inside while rho + 0.3 <= 0.5
        const Scene scene = disc_light_scene(a);
        for (double rho : {0.0, 0.1, 0.2}) {
            SCOPED_TRACE(rho);
            const double expected =
                closed_form(kRadius, rho, kHeight) - closed_form(2 * a, 2 * rho, kHeight);
            EXPECT_NEAR(floor_irradiance(scene, rho, 200000), expected, 0.01 * expected);
        }
    }
}

// Photons of the whole emission: each carries the whole flux (one of one sent), and the share
// landing on a coaxial floor disc is the disc-to-disc factor.
TEST(AreaLight, PhotonsLandAsTheDiscToDiscFactorSays) {
    const Scene scene = disc_light_scene(0);
    const Light& light = *scene.lights()[0];
    Rng rng(11, 2);
    constexpr int kPhotons = 400000;
    constexpr double kTarget = 1.0;
    int inside = 0;
    for (int i = 0; i < kPhotons; ++i) {
        const PhotonStart s = light.sample_le(rng);
        ASSERT_EQ(s.scale, 1.0);
        ASSERT_LT(s.ray.direction.y, 0.0);
        const Vec3 at = s.ray.at(-s.ray.origin.y / s.ray.direction.y);
        if (at.x * at.x + at.z * at.z < kTarget * kTarget) ++inside;
    }
    const double expected = disc_to_disc(kRadius, kTarget, kHeight);
    EXPECT_NEAR(double(inside) / kPhotons, expected, 0.01 * expected);
}

// Aimed at a glass sphere, the photons' weights give the flux reaching it that unaimed ones
// count: the aimed stream is the same light, only denser.
TEST(AreaLight, AimedPhotonsCarryTheFluxUnaimedOnesFind) {
    const Scene scene = parse_scene(R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
        "objects": [{"type": "sphere", "center": [0.6, 0, 0.2], "radius": 0.3,
                     "material": {"transparency": 1, "ior": 1.5}}],
        "lights": [{"type": "rectangle_light", "center": [0, 2, 0], "normal": [0, -1, 0],
                    "size": [1.2, 0.6], "power": 10}]})");
    const Light& light = *scene.lights()[0];
    ASSERT_TRUE(light.worth_aiming(scene.photon_targets()));
    const auto hits = [&](const Ray& r) {
        SceneHit h;
        return scene.intersect(r, 1e-9, INFINITY, h);
    };
    Rng rng(5, 9);
    constexpr int kPhotons = 400000;
    double unaimed = 0, aimed = 0;
    for (int i = 0; i < kPhotons; ++i) {
        const PhotonStart s = light.sample_le(rng);
        if (hits(s.ray)) unaimed += s.scale;
        AimSample u;
        for (double& x : u) x = rng.uniform();
        const PhotonStart t = light.sample_le_towards(scene.photon_targets(), u);
        if (hits(t.ray)) aimed += t.scale;
    }
    EXPECT_GT(unaimed, 0);
    EXPECT_NEAR(aimed / kPhotons, unaimed / kPhotons, 0.03 * unaimed / kPhotons);
}

// A floor under a rectangle light in every integrator: each lights it, and the two unbiased
// ones (the path tracer and sppm) agree on its brightness.
TEST(AreaLight, EveryIntegratorRendersIt) {
    Scene scene = parse_scene(R"({"camera": {"position": [0, 3, 3], "look_at": [0, 0, 0]},
        "render": {"width": 24, "height": 24},
        "objects": [{"type": "rectangle", "center": [0, 0, 0], "normal": [0, 1, 0],
                     "size": [6, 6], "material": {"color": 0.8}},
                    {"type": "sphere", "center": [0, 0.5, 0], "radius": 0.4,
                     "material": {"color": 0.5}}],
        "lights": [{"type": "rectangle_light", "center": [0, 2, 0], "normal": [0, -1, 0],
                    "size": [1, 1], "power": 20}]})");
    scene.render.light_samples = 4;
    std::map<std::string, double> mean;
    for (const char* integrator : {"whitted", "photon_map", "sppm", "path"}) {
        SCOPED_TRACE(integrator);
        Scene s = scene;
        s.render.integrator = integrator;
        s.render.spp = 64;
        s.render.passes = 64;
        s.render.photons = 20000;
        RenderControl control;
        const RenderResult r = render_scene(s, control);
        double g = 0;
        for (const PixelRgb& p : r.film.pixels()) g += p.g / r.film.pixels().size();
        EXPECT_GT(g, 0.01);
        mean[integrator] = g;
    }
    EXPECT_NEAR(mean["sppm"], mean["path"], 0.05 * mean["path"]);
}

}  // namespace
}  // namespace lenslab
