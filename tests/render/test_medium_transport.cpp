// Light in a participating medium against closed forms: free-flight sampling keeps
// Beer–Lambert's exp(-sigma_t d) in every band of a coloured medium, and the path tracer's
// single scattering from a point light or a small lamp matches the airlight integral, in the
// atmosphere and in a smoke box (and sppm's agrees with the path tracer's); an absorbing box
// dims what is behind it by exp(-sigma_t d).

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>

#include "math/constants.h"
#include "mean_green.h"
#include "render/medium_transport.h"
#include "render/render_session.h"
#include "scene/scene_json.h"
#include "util/scene_error.h"

namespace lenslab {
namespace {

using testing::mean_green_of_render;

// The mean weight of light passing a slab of thickness d is T = exp(-sigma_t d) in each band
// (Beer–Lambert), and that of light scattering within [0, d] is the integral of
// sigma_s exp(-sigma_t t), i.e. sigma_s / sigma_t (1 - T), even where the bands differ.
TEST(FreeFlight, KeepsBeerLambertInEveryBand) {
    Medium m;
    m.absorption = {0.2, 0.0, 0.5};
    m.scattering = {0.1, 0.4, 0.0};
    const double d = 1.5;
    Rng rng(5, 2);
    constexpr int kSamples = 400000;
    BandWeights passed{}, scattered{};
    for (int i = 0; i < kSamples; ++i) {
        const FreeFlight f = sample_free_flight(m, d, rng);
        BandWeights& sum = f.scattered ? scattered : passed;
        for (int b = 0; b < 3; ++b) sum[b] += f.weight[b] / kSamples;
        if (f.scattered) {
            EXPECT_LT(f.t, d);
        }
    }
    const BandWeights sigma_t = m.extinction();
    for (int b = 0; b < 3; ++b) {
        SCOPED_TRACE(b);
        const double t = std::exp(-sigma_t[b] * d);
        EXPECT_NEAR(passed[b], t, 0.005 * t);
        EXPECT_NEAR(scattered[b], m.scattering[b] / sigma_t[b] * (1 - t), 0.005);
    }
    // A clear band passes everything; no surface ahead: everything scatters in the end.
    const FreeFlight far = sample_free_flight(m, INFINITY, rng);
    EXPECT_TRUE(far.scattered);
}

// The airlight integral (Sun, Ramamoorthi, Narasimhan and Nayar 2005, "A practical analytic
// single scattering model for real time rendering", ACM TOG 24(3), eq. 1): the radiance a
// camera ray gathers from an isotropic point light of intensity I in a medium of scattering
// sigma (no absorption, isotropic phase 1/(4 pi)), the ray passing the light at distance h
// after running D to the closest point:
//   L = integral over s >= 0 of sigma exp(-sigma s) / (4 pi) * I exp(-sigma r) / r^2 ds,
//   r(s) = sqrt(h^2 + (s - D)^2).
// Evaluated here by Simpson's rule (the integrand is smooth; the tail beyond 40 free paths is
// below 1e-17).
// `entry`: where the ray enters the medium (0: it starts in it); the light is in the medium,
// and the stretch from it to each point of the ray too. `albedo`: sigma_s / sigma_t, sigma
// being sigma_t (an absorbing medium scatters that share).
double airlight(double sigma, double intensity, double h, double d, double entry = 0,
                double albedo = 1) {
    const int n = 400000;
    const double end = entry + 40 / sigma, step = (end - entry) / n;
    double sum = 0;
    for (int i = 0; i <= n; ++i) {
        const double s = entry + i * step;
        const double r2 = h * h + (s - d) * (s - d);
        const double f = albedo * sigma * std::exp(-sigma * (s - entry + std::sqrt(r2))) /
                         (4 * kPi) * intensity / r2;
        sum += f * ((i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2));
    }
    return sum * step / 3;
}

TEST(PathInMedium, SingleScatteringMatchesTheAirlightIntegral) {
    // Camera 5 units before the point closest to the light, passing it at h = 1; single
    // scattering only (max_depth 1: the first scattering point's direct light).
    const double sigma = 0.1, power = 50, h = 1, d = 5;
    Scene scene = parse_scene(R"({
      "camera": {"position": [1, 0, -5], "look_at": [1, 0, 0], "fov": 0.001},
      "render": {"width": 4, "height": 4, "spp": 10000, "max_depth": 1, "integrator": "path"},
      "atmosphere": {"scattering": 0.1},
      "lights": [{"type": "point", "position": [0, 0, 0], "power": 50}]
    })");
    const double mean = mean_green_of_render(scene);
    // The light's colour per watt of intensity: power / (4 pi) W/sr of white light renders as
    // its spectrum's colour over 4 pi.
    const double white = spectrum_to_rgb(*scene.point_lights[0].spectrum).g / power;
    const double expected = airlight(sigma, power / (4 * kPi), h, d) * white;
    EXPECT_NEAR(mean, expected, 0.02 * expected);
}

// An emitting sphere small beside h is a point light of intensity L pi r^2 (a Lambertian
// sphere of radiance L shows its projected disc every way): its single scattering, gathered
// along the ray by equiangular sampling towards its centre, matches the airlight integral
// too, here in a medium that also absorbs.
Scene emitting_sphere_in_fog(const std::string& integrator, int max_depth) {
    return parse_scene(R"({
      "camera": {"position": [1, 0, -5], "look_at": [1, 0, 0], "fov": 0.001},
      "render": {"width": 4, "height": 4, "spp": 10000, "passes": 64, "pass_photons": 20000,
                 "max_depth": )" +
                       std::to_string(max_depth) + R"(, "integrator": ")" + integrator + R"("},
      "atmosphere": {"scattering": 0.05, "absorption": 0.15},
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 0.02,
                   "material": {"color": 0, "emission": {"intensity": 40000}}}]
    })");
}

TEST(PathInMedium, SingleScatteringFromASmallEmittingSphereMatchesTheAirlightIntegral) {
    const double sigma_t = 0.2, albedo = 0.25, radius = 0.02, h = 1, d = 5;
    const Scene scene = emitting_sphere_in_fog("path", 1);
    const double mean = mean_green_of_render(scene);
    const double radiance_green = spectrum_to_rgb(*scene.material_of(0).emission).g;
    const double expected =
        airlight(sigma_t, kPi * radius * radius, h, d, 0, albedo) * radiance_green;
    EXPECT_NEAR(mean, expected, 0.02 * expected);
}

// sppm gathers the same single scattering along its camera segments and leaves the photons
// that come straight from the sphere out of its volume estimate: with every order of
// scattering, it agrees with the path tracer (neither counts the sphere's light twice or not
// at all: its single scattering is about 90% of the whole here).
TEST(SppmMedia, AnEmittingSpheresScatteringAgreesWithThePathTracer) {
    // A wider view than the airlight's pencil, so that sppm's volume photons (multiple
    // scattering) have pixel footprints to gather in; the sphere stays out of the picture.
    auto render = [](const std::string& integrator) {
        Scene scene = emitting_sphere_in_fog(integrator, 8);
        scene.camera.fov_deg = 20;
        scene.render.width = scene.render.height = 8;
        scene.render.spp = 2000;
        return mean_green_of_render(scene);
    };
    const double path = render("path"), sppm = render("sppm");
    ASSERT_GT(path, 0);
    EXPECT_NEAR(sppm, path, 0.04 * path);
}

// The same inside a smoke box seen from outside: the camera ray crosses the box's surfaceless
// wall 2 units ahead (clear air before it), and the shadow rays to the light, inside the
// box, run through the box's smoke alone.
TEST(PathInMedium, SingleScatteringInASmokeBoxMatchesTheAirlightIntegral) {
    const double sigma = 0.1, power = 50, h = 1, d = 5, entry = 2;
    Scene scene = parse_scene(R"({
      "camera": {"position": [1, 0, -5], "look_at": [1, 0, 0], "fov": 0.001},
      "render": {"width": 4, "height": 4, "spp": 10000, "max_depth": 1, "integrator": "path"},
      "objects": [{"type": "box", "center": [0, 0, 200], "size": [400, 400, 406],
                   "medium": {"scattering": 0.1}}],
      "lights": [{"type": "point", "position": [0, 0, 0], "power": 50}]
    })");
    const double mean = mean_green_of_render(scene);
    const double white = spectrum_to_rgb(*scene.point_lights[0].spectrum).g / power;
    const double expected = airlight(sigma, power / (4 * kPi), h, d, entry) * white;
    EXPECT_NEAR(mean, expected, 0.02 * expected);
}

// Beer–Lambert through surfaceless boundaries: a camera ray through an absorbing box of
// thickness 2 (and, around it, an absorbing atmosphere over 9 + 14 units) sees
// exp(-sigma_box 2 - sigma_air 23) of the emitting sphere behind, exactly but for the film's
// float pixels (a medium that only absorbs weights each path by its transmittance).
TEST(PathInMedium, AbsorbingBoxKeepsBeerLambertsFraction) {
    const auto render = [](const std::string& media) {
        return mean_green_of_render(parse_scene(R"({
          "camera": {"position": [0, 0, -10], "look_at": [0, 0, 0], "fov": 0.001},
          "render": {"width": 2, "height": 2, "spp": 16, "integrator": "path"},
          "objects": [{"type": "sphere", "center": [0, 0, 20], "radius": 5,
                       "material": {"color": 0, "emission": {"intensity": 1}}})" +
                                                media + "}"));
    };
    const double clear = render("]");
    ASSERT_GT(clear, 0);
    for (const double sigma : {0.1, 0.5, 2.0}) {
        SCOPED_TRACE(sigma);
        const std::string box = R"(, {"type": "box", "center": [0, 0, 0], "size": [4, 4, 2],
                                      "medium": {"absorption": )" +
                                std::to_string(sigma) + "}}]";
        // To the film's float precision.
        const double box_only = std::exp(-sigma * 2);
        EXPECT_NEAR(render(box) / clear, box_only, 1e-6 * box_only);
        const double in_air = std::exp(-sigma * 2 - 0.05 * 23);
        EXPECT_NEAR(render(box + R"(, "atmosphere": {"absorption": 0.05})") / clear, in_air,
                    1e-6 * in_air);
    }
}

// A shadow ray from inside a smoke box to a light outside keeps exp(-sigma d) of each medium
// it crosses: 2 units of the box's smoke, then 8 of the atmosphere; a glass lens in the way
// blocks it (shadow rays do not refract); the box's walls do not.
TEST(ShadowTransmittance, MultipliesTheMediaCrossed) {
    const Scene scene = parse_scene(R"({
      "camera": {"position": [0, 0, -10], "look_at": [0, 0, 0]},
      "atmosphere": {"absorption": [0.1, 0.2, 0.3]},
      "objects": [
        {"type": "box", "center": [0, 0, 0], "size": [4, 4, 4], "medium": {"scattering": 0.5}},
        {"type": "sphere", "center": [0, 1, 0], "radius": 0.5,
         "material": {"transparency": 1, "ior": 1.5}}]
    })");
    // The coefficients per band, as the colours became them.
    const BandWeights air = scene.atmosphere->extinction();
    const BandWeights smoke = scene.objects[0].medium->extinction();
    Rng rng(1, 1);  // homogeneous media draw nothing from it
    const BandWeights tr = shadow_transmittance(scene, {0, 0, 0}, {1, 0, 0}, 10, rng);
    for (int b = 0; b < 3; ++b) EXPECT_NEAR(tr[b], std::exp(-smoke[b] * 2 - air[b] * 8), 1e-12);
    // From outside, through the whole box: 4 units of smoke, 6 of air.
    const BandWeights across = shadow_transmittance(scene, {-5, -1, 0}, {1, 0, 0}, 10, rng);
    for (int b = 0; b < 3; ++b) {
        EXPECT_NEAR(across[b], std::exp(-smoke[b] * 4 - air[b] * 6), 1e-12);
    }
    const BandWeights blocked = shadow_transmittance(scene, {0, 0, 0}, {0, 1, 0}, 10, rng);
    for (int b = 0; b < 3; ++b) EXPECT_EQ(blocked[b], 0.0);
}

// A camera ray crossing a laser-like beam at right angles through its axis gathers, from
// single isotropic scattering (the same integral as the airlight's, with the beam's
// irradiance P / (pi r^2) arriving along it from its disc 10 units away):
//   L = sigma / (4 pi) * P / (pi r^2) * exp(-10 sigma) * integral over the chord
//       [D - r, D + r] of exp(-sigma t) dt.
TEST(PathInMedium, SingleScatteringFromABeamMatchesItsClosedForm) {
    const double sigma = 0.05, power = 2, r = 0.2, d = 5;
    Scene scene = parse_scene(R"({
      "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov": 0.001},
      "render": {"width": 2, "height": 2, "spp": 64, "max_depth": 1, "integrator": "path"},
      "atmosphere": {"scattering": 0.05},
      "lights": [{"type": "beam", "origin": [-10, 0, 0], "direction": [1, 0, 0],
                  "radius": 0.2, "power": 2}]
    })");
    const double mean = mean_green_of_render(scene);
    const double white = spectrum_to_rgb(*scene.beams[0].spectrum).g / power;
    const double chord = (std::exp(-sigma * (d - r)) - std::exp(-sigma * (d + r))) / sigma;
    const double expected =
        sigma / (4 * kPi) * power / (kPi * r * r) * std::exp(-10 * sigma) * chord * white;
    EXPECT_NEAR(mean, expected, 0.01 * expected);
}

// The same for a line laser's fan crossed at right angles through its sheet 10 units from the
// aperture (in the sheet), where the irradiance is P / (theta rho 2r) all along the chord
// [D - r, D + r]; and for a beam through a slit, crossed through the slit, whose chord the
// strip cuts to [D - w/2, D + w/2], lit with P / A, A the disc's area inside the strip.
TEST(PathInMedium, SingleScatteringFromAFanAndASlitMatchesTheirClosedForms) {
    const double sigma = 0.05, power = 2, r = 0.2, d = 5, theta = kPi / 3;
    Scene fan = parse_scene(R"({
      "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov": 0.001},
      "render": {"width": 2, "height": 2, "spp": 64, "max_depth": 1, "integrator": "path"},
      "atmosphere": {"scattering": 0.05},
      "lights": [{"type": "beam", "origin": [-10, 0, 0], "direction": [1, 0, 0],
                  "radius": 0.2, "power": 2, "fan_angle": 60, "fan_axis": [0, 1, 0]}]
    })");
    const double white = spectrum_to_rgb(*fan.beams[0].spectrum).g / power;
    const double fan_chord = (std::exp(-sigma * (d - r)) - std::exp(-sigma * (d + r))) / sigma;
    const double fan_expected = sigma / (4 * kPi) * power / (theta * 10 * 2 * r) *
                                std::exp(-10 * sigma) * fan_chord * white;
    const double fan_mean = mean_green_of_render(fan);
    EXPECT_NEAR(fan_mean, fan_expected, 0.01 * fan_expected);

    Scene slit = parse_scene(R"({
      "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov": 0.001},
      "render": {"width": 2, "height": 2, "spp": 64, "max_depth": 1, "integrator": "path"},
      "atmosphere": {"scattering": 0.05},
      "lights": [{"type": "beam", "origin": [-10, 0, 0], "direction": [1, 0, 0],
                  "radius": 0.2, "power": 2, "slit_width": 0.2}]
    })");
    const double h = 0.1;
    const double area = 2 * (h * std::sqrt(r * r - h * h) + r * r * std::asin(h / r));
    const double slit_chord = (std::exp(-sigma * (d - h)) - std::exp(-sigma * (d + h))) / sigma;
    const double slit_expected =
        sigma / (4 * kPi) * power / area * std::exp(-10 * sigma) * slit_chord * white;
    const double slit_mean = mean_green_of_render(slit);
    EXPECT_NEAR(slit_mean, slit_expected, 0.01 * slit_expected);
}

// The integrators without media would render the scene as if the air were clear: they
// refuse an atmosphere and a shape's medium, naming it.
TEST(PathInMedium, IntegratorsWithoutMediaRefuseMedia) {
    const std::pair<const char*, const char*> media[] = {
        {R"("atmosphere": {"scattering": 0.1},
            "objects": [],)",
         "atmosphere"},
        {R"("objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
                         "material": {"color": 0.5}},
                        {"type": "sphere", "center": [0, 0, 0], "radius": 2,
                         "medium": {"scattering": 0.1}}],)",
         "objects[1].medium"}};
    for (const auto& [medium, path] : media) {
        for (const char* integrator : {"whitted", "photon_map"}) {
            Scene scene = parse_scene(R"({
              "camera": {"position": [1, 0, -5], "look_at": [1, 0, 0]},
              "render": {"width": 4, "height": 4, "integrator": ")" +
                                      std::string(integrator) + R"("},)" + medium + R"(
              "lights": [{"type": "point", "position": [0, 3, 0], "power": 50}]
            })");
            RenderControl control;
            try {
                (void)render_scene(scene, control);
                ADD_FAILURE() << integrator << " rendered";
            } catch (const SceneError& e) {
                EXPECT_EQ(e.path(), path);
            }
        }
    }
}

}  // namespace
}  // namespace lenslab
