// Detectors under the lights teachers use (light.h): a line laser's fan and a beam through a
// slit, against geometry alone. Photon counts and the Monte Carlo sigma of each check are
// given where it is made; seeds are the detectors' own (deterministic).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "analysis/detectors/detector.h"
#include "math/constants.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

DetectorMeasurement measure_one_lights(const std::string& text, int64_t photons) {
    const DetectionResult r = measure_detectors(parse_scene(text), {.photons_per_light = photons});
    EXPECT_EQ(r.detectors.size(), 1u);
    return r.detectors.at(0);
}

// The disc of radius r inside the strip |x| <= h.
double lights_disc_in_strip(double r, double h) {
    return 2 * (h * std::sqrt(r * r - h * h) + r * r * std::asin(h / r));
}

// A 60-degree fan (P = 2 W) along +x spreading along z, and a screen across it at x = d = 2
// covering |z| <= d tan(alpha), alpha = 15 degrees, in 16 columns. Each photon leaves at an
// angle uniform in [-30, 30] degrees, so the screen receives P 2 alpha / theta = P / 2, and a
// column from z0 to z1 receives P (atan(z1 / d) - atan(z0 / d)) / theta. 400000 photons: the
// whole screen's sigma is 0.16%, a column's (about 1/32 of the photons) 0.9%.
TEST(DetectorLights, FanSpreadsItsPowerUniformlyInAngle) {
    const double p = 2, d = 2, theta = kPi / 3, alpha = kPi / 12;
    const double width = 2 * d * std::tan(alpha);
    char text[1024];
    std::snprintf(text, sizeof text, R"({"camera": {"position": [0, 5, 5], "look_at": [0, 0, 0]},
        "objects": [{"type": "rectangle", "center": [2, 0, 0], "normal": [-1, 0, 0],
                     "size": [%.17g, 0.5], "material": {"color": 0.5},
                     "detector": {"resolution": [16, 1]}}],
        "lights": [{"type": "laser", "position": [0, 0, 0], "direction": [1, 0, 0],
                    "radius": 0.01, "power": 2, "fan_angle": 60}]})",
                  width);
    const DetectorMeasurement m = measure_one_lights(text, 400000);
    const double expected = p * 2 * alpha / theta;
    std::printf("fan: P = %.5f W on the screen, expected %.5f W (%+.3f%%)\n", m.total_power,
                expected, 100 * (m.total_power / expected - 1));
    EXPECT_NEAR(m.total_power, expected, 0.008 * expected);
    const DetectorGrid& g = m.grid;
    ASSERT_EQ(g.cells_u(), 16);
    for (int c = 0; c < 16; ++c) {
        const double z0 = g.cell_u(c) - 0.5 * g.cell_width(), z1 = z0 + g.cell_width();
        const double column = p * std::abs(std::atan(z1 / d) - std::atan(z0 / d)) / theta;
        EXPECT_NEAR(m.power[static_cast<size_t>(c)], column, 0.05 * column) << "column " << c;
    }
}

std::string slit_scene_lights(double screen_width) {
    char text[1024];
    std::snprintf(text, sizeof text, R"({"camera": {"position": [0, 5, 5], "look_at": [0, 0, 0]},
        "objects": [{"type": "rectangle", "center": [0, 0, 1], "normal": [0, 0, -1],
                     "size": [%.17g, 2], "material": {"color": 0.5}, "detector": true}],
        "lights": [{"type": "beam", "origin": [0, 0, -1], "direction": [0, 0, 1],
                    "radius": 0.5, "power": 3, "slit_width": 0.4}]})",
                  screen_width);
    return text;
}

// A 3 W white beam of radius 0.5 through a slit 0.4 wide (|x| <= 0.2). A screen wider than
// the beam receives all 3 W (every photon, each carrying 3 W / N); a strip |x| <= 0.1 the
// share of the open area it covers, A(0.1) / A(0.2) = 0.511. 200000 photons: sigma 0.22%.
TEST(DetectorLights, SlitSendsItsPowerThroughTheOpenArea) {
    const DetectorMeasurement all = measure_one_lights(slit_scene_lights(2), 200000);
    std::printf("slit: P = %.6f W through it, expected 3 W\n", all.total_power);
    EXPECT_NEAR(all.total_power, 3, 1e-6);
    const DetectorMeasurement strip = measure_one_lights(slit_scene_lights(0.2), 200000);
    const double expected = 3 * lights_disc_in_strip(0.5, 0.1) / lights_disc_in_strip(0.5, 0.2);
    std::printf("slit: P = %.5f W on the central strip, expected %.5f W (%+.3f%%)\n",
                strip.total_power, expected, 100 * (strip.total_power / expected - 1));
    EXPECT_NEAR(strip.total_power, expected, 0.01 * expected);
}

}  // namespace
}  // namespace lenslab
