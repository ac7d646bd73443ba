// Heterogeneous media (a density f(x, y, z) multiplying both coefficients) against closed
// forms. Along a ray through a linear density f = a + b z the optical depth over a distance
// d is tau = sigma_t (a d + b d^2 / 2), so Beer–Lambert's transmittance is exp(-tau): ratio
// tracking estimates it, delta tracking's first collision lies beyond d with that
// probability, and free-flight sampling keeps it in every band of a coloured medium. A
// constant density of 1 is the homogeneous medium; the path tracer and sppm agree in a
// heterogeneous fog; photons crossing a heterogeneous absorbing box reach a detector with
// Beer–Lambert's share.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "analysis/detectors/detector.h"
#include "mean_green.h"
#include "render/density_tracking.h"
#include "render/medium_transport.h"
#include "render/render_session.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

// f = 0.5 + 0.8 z in a box around the ray from the origin along +z.
constexpr double kA = 0.5, kB = 0.8;
const Aabb kLinearBox{{-1, -1, 0}, {1, 1, 4}};
const Ray kAlongZ{{0, 0, 0}, {0, 0, 1}};

Medium linear_medium(const std::string& coefficients) {
    return read_medium(
        nlohmann::json::parse(R"({"density": "0.5 + 0.8 * z", )" + coefficients + "}"), "medium",
        kLinearBox);
}

// The integral of f = a + b z from 0 to d.
double linear_depth(double d) { return kA * d + kB * d * d / 2; }

TEST(HeterogeneousMedium, RatioTrackingKeepsBeerLambertOfALinearDensity) {
    const Medium m = linear_medium(R"("absorption": 0.6)");
    const double d = 2, expected = std::exp(-0.6 * linear_depth(d));
    Rng rng(3, 7);
    constexpr int kSamples = 200000;
    double mean = 0, mean_bands = 0;
    for (int i = 0; i < kSamples; ++i) {
        mean += ratio_track(*m.density, 0.6, kAlongZ, d, rng) / kSamples;
        mean_bands += ratio_track(m, kAlongZ, d, rng)[1] / kSamples;
    }
    std::printf("ratio tracking %.5f, per band %.5f, exp(-tau) %.5f\n", mean, mean_bands, expected);
    // Each estimate lies in [0, 1]: the standard error is below 0.5 / sqrt(2e5) = 0.0011.
    EXPECT_NEAR(mean, expected, 0.005);
    EXPECT_NEAR(mean_bands, expected, 0.005);
}

// The same density as samples on a grid along z (trilinear interpolation is exact for a
// linear f): the same transmittance.
TEST(HeterogeneousMedium, AGridOfTheLinearDensityKeepsItsBeerLambert) {
    const Medium m = read_medium(nlohmann::json::parse(R"({"absorption": 0.6, "density":
        {"grid": [1, 1, 5], "box": [[-1, -1, 0], [1, 1, 4]], "values": [0.5, 1.3, 2.1, 2.9, 3.7]}})"),
                                 "medium", kLinearBox);
    Rng rng(8, 9);
    constexpr int kSamples = 200000;
    double mean = 0;
    for (int i = 0; i < kSamples; ++i) mean += ratio_track(m, kAlongZ, 2, rng)[0] / kSamples;
    std::printf("grid: ratio tracking %.5f, exp(-tau) %.5f\n", mean,
                std::exp(-0.6 * linear_depth(2)));
    EXPECT_NEAR(mean, std::exp(-0.6 * linear_depth(2)), 0.005);
}

TEST(HeterogeneousMedium, DeltaTrackingCollidesWithBeerLambertsProbability) {
    const Medium m = linear_medium(R"("scattering": 0.6)");
    Rng rng(4, 1);
    constexpr int kSamples = 200000;
    int beyond_half = 0, beyond = 0;
    for (int i = 0; i < kSamples; ++i) {
        const double t = delta_track(*m.density, 0.6, kAlongZ, 2.0, rng);
        beyond_half += t >= 1.0;
        beyond += t >= 2.0;
    }
    std::printf("beyond 1: %.5f (%.5f), beyond 2: %.5f (%.5f)\n", double(beyond_half) / kSamples,
                std::exp(-0.6 * linear_depth(1)), double(beyond) / kSamples,
                std::exp(-0.6 * linear_depth(2)));
    // P(no collision before s) = exp(-sigma (a s + b s^2 / 2)); binomial standard errors
    // below 0.0012.
    EXPECT_NEAR(double(beyond_half) / kSamples, std::exp(-0.6 * linear_depth(1)), 0.005);
    EXPECT_NEAR(double(beyond) / kSamples, std::exp(-0.6 * linear_depth(2)), 0.005);
}

// As the homogeneous FreeFlight test: per band, the mean weight of light passing is
// T = exp(-sigma_t tau) and that of light scattering sigma_s / sigma_t (1 - T), the bands
// differing, here with tau the linear density's depth.
TEST(HeterogeneousMedium, FreeFlightKeepsBeerLambertInEveryBand) {
    const Medium m = linear_medium(R"("absorption": [0.2, 0.0, 0.5], "scattering": [0.1, 0.4, 0])");
    const BandWeights sigma_t = m.extinction(), sigma_s = m.scattering;
    const double d = 1.5, depth = linear_depth(d);
    Rng rng(5, 2);
    constexpr int kSamples = 200000;
    BandWeights passed{}, scattered{};
    for (int i = 0; i < kSamples; ++i) {
        const FreeFlight f = sample_free_flight(m, kAlongZ, d, rng);
        BandWeights& sum = f.scattered ? scattered : passed;
        for (int b = 0; b < 3; ++b) sum[b] += f.weight[b] / kSamples;
        if (f.scattered) {
            EXPECT_LT(f.t, d);
        }
    }
    for (int b = 0; b < 3; ++b) {
        SCOPED_TRACE(b);
        const double t = std::exp(-sigma_t[b] * depth);
        std::printf("band %d: passed %.5f (%.5f), scattered %.5f (%.5f)\n", b, passed[b], t,
                    scattered[b], sigma_s[b] / sigma_t[b] * (1 - t));
        EXPECT_NEAR(passed[b], t, 0.01 * t);
        EXPECT_NEAR(scattered[b], sigma_s[b] / sigma_t[b] * (1 - t), 0.006);
    }
}

// A shadow ray crossing a smoke box with the linear density (z from 0.5 to 2.5 inside the
// box): its mean transmittance is exp(-sigma_t \int_0.5^2.5 f dz); the clear air outside
// costs nothing.
TEST(HeterogeneousMedium, ShadowTransmittanceThroughADensityBox) {
    const Scene scene = parse_scene(R"({
      "camera": {"position": [0, 0, -10], "look_at": [0, 0, 0]},
      "objects": [{"type": "box", "center": [0, 0, 1.5], "size": [2, 2, 2],
                   "medium": {"scattering": 0.3, "absorption": 0.2, "density": "0.5 + 0.8 * z"}}]
    })");
    Rng rng(6, 3);
    constexpr int kSamples = 100000;
    double mean = 0;
    for (int i = 0; i < kSamples; ++i)
        mean += shadow_transmittance(scene, {0, 0, -1}, {0, 0, 1}, 5, rng)[0] / kSamples;
    const double expected = std::exp(-0.5 * (linear_depth(2.5) - linear_depth(0.5)));
    std::printf("shadow transmittance %.5f, expected %.5f\n", mean, expected);
    EXPECT_NEAR(mean, expected, 0.005);
}

// Single scattering of a point light seen through a fog box: a density of "1" is the
// homogeneous medium, up to the noise of tracking (the homogeneous render's own noise is
// far below 1% at this many samples).
TEST(HeterogeneousMedium, ADensityOfOneRendersAsTheHomogeneousMedium) {
    const auto render = [](const std::string& density) {
        return testing::mean_green_of_render(parse_scene(R"({
          "camera": {"position": [1, 0, -5], "look_at": [1, 0, 0], "fov": 0.001},
          "render": {"width": 2, "height": 2, "spp": 4000, "max_depth": 1, "integrator": "path"},
          "objects": [{"type": "box", "center": [0, 0, 0], "size": [8, 8, 8],
                       "medium": {"scattering": 0.2, "absorption": 0.1)" +
                                                         density + R"(}}],
          "lights": [{"type": "point", "position": [0, 0, 0], "power": 50}]
        })"));
    };
    const double homogeneous = render(""), one = render(R"(, "density": "1")");
    std::printf("homogeneous %.6g, density 1 %.6g (ratio %.4f)\n", homogeneous, one,
                one / homogeneous);
    ASSERT_GT(homogeneous, 0);
    EXPECT_NEAR(one, homogeneous, 0.03 * homogeneous);
}

// A lamp in a fog whose density falls off away from it, seen with every order of
// scattering: sppm (single scattering summed along camera segments with ratio tracking,
// the rest from photons placed by delta tracking) agrees with the path tracer (the unbiased
// reference). sppm's kernel estimate is biased low in this dense fog until its radii have
// shrunk: sppm / path measured 0.951 after 48 passes of 20000 photons, 0.969 after 192, 0.988
// after 768; 0.977 after the 256 passes of 10000 here (a homogeneous fog of density 1: 1.003
// after 192).
TEST(HeterogeneousMedium, SppmAgreesWithThePathTracerInAHeterogeneousFog) {
    const auto render = [](const std::string& integrator) {
        return testing::mean_green_of_render(parse_scene(R"({
          "camera": {"position": [1, 0, -5], "look_at": [1, 0, 0], "fov": 20},
          "render": {"width": 8, "height": 8, "spp": 1500, "passes": 256, "pass_photons": 10000,
                     "max_depth": 8, "integrator": ")" + integrator +
                                                         R"j("},
          "objects": [
            {"type": "box", "center": [0, 0, 0], "size": [6, 6, 6],
             "medium": {"scattering": 0.3, "absorption": 0.1,
                        "density": "0.2 + 1.5 * exp(-(x * x + y * y + z * z))"}},
            {"type": "sphere", "center": [0, 0, 0], "radius": 0.05,
             "material": {"color": 0, "emission": {"intensity": 5000}}}]
        })j"));
    };
    const double path = render("path"), sppm = render("sppm");
    std::printf("path %.6g, sppm %.6g (ratio %.4f)\n", path, sppm, sppm / path);
    ASSERT_GT(path, 0);
    EXPECT_NEAR(sppm, path, 0.05 * path);
}

// Photons crossing a box of absorbing smoke whose density grows downwards, f = 1 + (2.5 - y)
// for y in [0.5, 2.5] (\int f dy = 2 + 2 = 4), reach the detector below with exp(-sigma 4)
// of the beam's power on average (ratio tracking dims each by an unbiased estimate).
TEST(HeterogeneousMedium, PhotonsThroughAnAbsorbingDensityKeepBeerLambertsShare) {
    const double sigma = 0.3;
    const Scene scene = parse_scene(R"j({"camera": {"position": [0, 5, 5], "look_at": [0, 0, 0]},
        "objects": [
          {"type": "disc", "center": [0, 0, 0], "normal": [0, 1, 0], "radius": 0.5,
           "material": {"color": 0}, "detector": true},
          {"type": "box", "center": [0, 1.5, 0], "size": [2, 2, 2],
           "medium": {"absorption": 0.3, "density": "1 + (2.5 - y)"}}],
        "lights": [{"type": "beam", "origin": [0, 3, 0], "direction": [0, -1, 0],
                    "radius": 0.1, "power": 1}]})j");
    const double p =
        measure_detectors(scene, {.photons_per_light = 40000}).detectors.at(0).total_power;
    const double expected = std::exp(-sigma * 4);
    std::printf("detector %.5f W, exp(-sigma 4) %.5f W\n", p, expected);
    EXPECT_NEAR(p, expected, 0.02 * expected);
}

}  // namespace
}  // namespace lenslab
