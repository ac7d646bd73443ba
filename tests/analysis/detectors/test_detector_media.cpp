// Detectors behind participating media, against physics: Beer–Lambert through absorbing fog
// (exactly, for several coefficients and per wavelength band), the narrow-beam attenuation
// exp(-sigma_t d) when the fog also scatters, and conservation of power in a box of fog that
// scatters without absorbing.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "analysis/detectors/detector.h"
#include "optics/spectrum.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

DetectionResult measure_in_fog(const Scene& scene, int64_t photons, int max_depth = 8) {
    return measure_detectors(scene, {.photons_per_light = photons, .max_depth = max_depth});
}

// A 1 W beam of radius 0.1 going down from height d onto a detector disc of radius `disc`
// at the origin, facing up, through the given atmosphere.
Scene beam_through(const std::string& atmosphere, double d, const std::string& light_extra,
                   double disc = 0.5) {
    return parse_scene(R"({"camera": {"position": [0, 5, 5], "look_at": [0, 0, 0]},
        "atmosphere": )" +
                       atmosphere + R"(,
        "objects": [{"type": "disc", "center": [0, 0, 0], "normal": [0, 1, 0], "radius": )" +
                       std::to_string(disc) + R"(,
                     "material": {"color": 0}, "detector": true}],
        "lights": [{"type": "beam", "origin": [0, )" +
                       std::to_string(d) + R"(, 0],
                    "direction": [0, -1, 0], "radius": 0.1, "power": 1)" +
                       light_extra + "}]}");
}

TEST(DetectorMedia, AbsorbingFogLeavesExactlyTheBeerLambertShare) {
    // Beer and Lambert: a beam crossing a thickness d of a medium that absorbs sigma per unit
    // keeps exp(-sigma d) of its power. Every photon travels exactly d, so the detector reads
    // the share to rounding, not within noise.
    const double d = 2.0;
    for (const double sigma : {0.1, 0.5, 2.0}) {
        const Scene scene = beam_through(R"({"absorption": )" + std::to_string(sigma) + "}", d, "");
        const double p = measure_in_fog(scene, 5000).detectors.at(0).total_power;
        const double expected = std::exp(-sigma * d);
        std::printf("sigma_a %.2f: P = %.9f W, exp(-sigma d) = %.9f\n", sigma, p, expected);
        EXPECT_NEAR(p, expected, 1e-9);
    }
}

TEST(DetectorMedia, EachWavelengthKeepsTheShareOfItsOwnCoefficient) {
    // Coloured fog: red, green and blue laser lines each keep exp(-sigma(lambda) d), sigma
    // that of the band their wavelength falls in.
    const double d = 1.5;
    for (const double nm : {450.0, 532.0, 632.8}) {
        const Scene scene = beam_through(R"({"absorption": [0.2, 0.6, 1.4]})", d,
                                         R"(, "spectrum": {"line": )" + std::to_string(nm) + "}");
        const double sigma = scene.atmosphere->absorption[static_cast<size_t>(band_of(nm))];
        const double p = measure_in_fog(scene, 5000).detectors.at(0).total_power;
        const double expected = std::exp(-sigma * d);
        std::printf("%.1f nm: sigma_a %.4f, P = %.9f W, expected %.9f\n", nm, sigma, p, expected);
        EXPECT_GT(sigma, 0.0);
        EXPECT_NEAR(p, expected, 1e-9);
    }
}

TEST(DetectorMedia, ScatteringFogAttenuatesANarrowBeamByTheExtinction) {
    // Narrow-beam geometry: a detector disc of radius a = 0.01 in a uniform beam of radius
    // b = 0.011 receives (a / b)^2 exp(-(sigma_a + sigma_s) d) of its power from light that
    // never scattered. What isotropic fog scatters onto the disc from just above it adds
    // about sigma_s a / 2 = 0.15% of that, and the light that wanders off and comes back adds
    // less the narrower the beam (1.4% with a = b = 0.1, 0.02% here).
    const double d = 2.0, sigma_a = 0.2, sigma_s = 0.3, a = 0.01, b = 0.011;
    const Scene scene = parse_scene(R"({"camera": {"position": [0, 5, 5], "look_at": [0, 0, 0]},
        "atmosphere": {"absorption": 0.2, "scattering": 0.3},
        "objects": [{"type": "disc", "center": [0, 0, 0], "normal": [0, 1, 0], "radius": 0.01,
                     "material": {"color": 0}, "detector": true}],
        "lights": [{"type": "beam", "origin": [0, 2, 0], "direction": [0, -1, 0],
                    "radius": 0.011, "power": 1}]})");
    const double p = measure_in_fog(scene, 400000).detectors.at(0).total_power;
    const double expected = (a / b) * (a / b) * std::exp(-(sigma_a + sigma_s) * d);
    std::printf("P = %.5f W, (a/b)^2 exp(-sigma_t d) = %.5f (%+.2f%%)\n", p, expected,
                100 * (p / expected - 1));
    EXPECT_NEAR(p, expected, 0.01 * expected);
}

TEST(DetectorMedia, ABoxOfScatteringFogLetsOutAllTheLightInside) {
    // Energy: a 10 W point light in fog that scatters (optical depth 1.5 from the centre to
    // each wall) and absorbs nothing, inside a closed box of six black detector walls: every
    // photon leaves the fog through one wall, whatever its scatterings, so the walls together
    // receive the 10 W, and each a sixth of it by symmetry.
    const Scene scene = parse_scene(R"({"camera": {"position": [0, 0, 0.5], "look_at": [0, 0, 0]},
        "atmosphere": {"scattering": 1.5, "g": 0.3},
        "materials": {"wall": {"color": 0}},
        "objects": [
          {"type": "rectangle", "center": [1, 0, 0], "normal": [-1, 0, 0], "size": [2, 2], "material": "wall", "detector": true},
          {"type": "rectangle", "center": [-1, 0, 0], "normal": [1, 0, 0], "size": [2, 2], "material": "wall", "detector": true},
          {"type": "rectangle", "center": [0, 1, 0], "normal": [0, -1, 0], "size": [2, 2], "material": "wall", "detector": true},
          {"type": "rectangle", "center": [0, -1, 0], "normal": [0, 1, 0], "size": [2, 2], "material": "wall", "detector": true},
          {"type": "rectangle", "center": [0, 0, 1], "normal": [0, 0, -1], "size": [2, 2], "material": "wall", "detector": true},
          {"type": "rectangle", "center": [0, 0, -1], "normal": [0, 0, 1], "size": [2, 2], "material": "wall", "detector": true}],
        "lights": [{"type": "point", "position": [0, 0, 0], "power": 10}]})");
    const DetectionResult r = measure_in_fog(scene, 100000, 1000);
    double total = 0;
    for (const DetectorMeasurement& m : r.detectors) {
        total += m.total_power;
        EXPECT_NEAR(m.total_power, 10.0 / 6, 0.05 * 10.0 / 6) << m.name;
    }
    std::printf("power out through the six walls: %.6f W of 10 W\n", total);
    EXPECT_NEAR(total, 10.0, 1e-3);
}

}  // namespace
}  // namespace lenslab
