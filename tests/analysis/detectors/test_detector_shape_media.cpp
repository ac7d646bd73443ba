// Detectors behind media in shapes: a beam crossing an absorbing box of smoke (a shape with
// a medium and no material, so its walls neither refract nor reflect) reaches a detector with
// exactly the Beer–Lambert share exp(-sigma_a d) of its power.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "analysis/detectors/detector.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

TEST(DetectorShapeMedia, AbsorbingBoxLeavesExactlyTheBeerLambertShare) {
    // A 1 W beam going down from y = 3 onto a detector disc at the origin through a box
    // 2 units thick (y from 0.5 to 2.5); the air around the box is clear.
    const double d = 2.0;
    for (const double sigma : {0.1, 0.5, 2.0}) {
        SCOPED_TRACE(sigma);
        const Scene scene = parse_scene(R"({"camera": {"position": [0, 5, 5], "look_at": [0, 0, 0]},
            "objects": [
              {"type": "disc", "center": [0, 0, 0], "normal": [0, 1, 0], "radius": 0.5,
               "material": {"color": 0}, "detector": true},
              {"type": "box", "center": [0, 1.5, 0], "size": [2, 2, 2],
               "medium": {"absorption": )" +
                                        std::to_string(sigma) +
                                        R"(}}],
            "lights": [{"type": "beam", "origin": [0, 3, 0], "direction": [0, -1, 0],
                        "radius": 0.1, "power": 1}]})");
        const double p =
            measure_detectors(scene, {.photons_per_light = 5000}).detectors.at(0).total_power;
        EXPECT_NEAR(p, std::exp(-sigma * d), 1e-9);
    }
}

}  // namespace
}  // namespace lenslab
