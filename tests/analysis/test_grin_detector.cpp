// The photon tracer through a gradient-index solid: a Luneburg lens delivers a whole beam to
// one point of its rim, with no Fresnel loss (n = 1 at its surface, where it meets air).

#include <gtest/gtest.h>

#include <cstdio>

#include "analysis/detectors/detector.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

TEST(GrinDetector, LuneburgLensDeliversTheWholeBeamToItsRimPoint) {
    // Luneburg (1944): n = sqrt(2 - r^2/R^2) focuses a parallel beam on the rim point opposite
    // its entry. A detector disc 1e-4 R beyond that point receives every photon of a 1 W beam
    // (radius 0.9 R), spread only by the 1e-4 R the rays travel after leaving at up to
    // asin(0.9) = 64 degrees from the axis: RMS radius under 2.1e-4 R.
    const Scene scene = parse_scene(R"({"camera": {"position": [0, 0, -5], "look_at": [0, 0, 0]},
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
                   "material": {"transparency": 1, "grin": {"profile": "luneburg", "radius": 1}}},
                  {"name": "focus", "type": "disc", "center": [0, 0, 1.0001], "normal": [0, 0, -1],
                   "radius": 0.01, "material": {"color": 0.5}, "detector": {"resolution": 16}}],
      "lights": [{"type": "beam", "origin": [0, 0, -3], "direction": [0, 0, 1], "radius": 0.9,
                  "power": 1}]})");
    RenderControl control;
    DetectionSettings settings;
    settings.photons_per_light = 20000;
    const DetectionResult r = measure_detectors(scene, settings, control);
    ASSERT_EQ(r.detectors.size(), 1u);
    const DetectorMeasurement& m = r.detectors[0];
    std::printf("Luneburg focus: P = %.6f W, RMS radius %.3e R\n", m.total_power, m.rms_radius);
    EXPECT_NEAR(m.total_power, 1.0, 1e-9);
    EXPECT_LT(m.rms_radius, 2.1e-4);
}

}  // namespace
}  // namespace lenslab
