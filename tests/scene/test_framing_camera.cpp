// A camera made for a scene file without one (scene/framing_camera.h): the whole scene in view.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scene/framing_camera.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

// Every corner of the scene's bounds lies within half the field of view of the camera's
// axis (so inside the picture at any aspect ratio of at least 1), in front of it.
void expect_all_in_view(const Scene& scene) {
    const CameraSettings camera = camera_from_json(framing_camera_json(scene));
    const Aabb b = scene.bounds();
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 p{corner & 1 ? b.hi.x : b.lo.x, corner & 2 ? b.hi.y : b.lo.y,
                     corner & 4 ? b.hi.z : b.lo.z};
        const Vec3 to = normalize(p - camera.position);
        const double angle = std::acos(std::clamp(dot(to, camera.direction), -1.0, 1.0));
        EXPECT_LT(angle * 180 / std::numbers::pi, 0.5 * camera.fov_deg) << "corner " << corner;
    }
}

TEST(FramingCamera, ALensFileWithoutACameraIsInView) {
    // A lens file as `lenslab analyze` reads it: lengths in mm, no camera.
    const Scene scene = parse_scene(R"({
      "objects": [{"type": "lens", "center": [0, 0, 20], "axis": [0, 0, 1], "diameter": 25.4,
                   "thickness": 6, "front": {"shape": "sphere", "radius": 50},
                   "back": {"shape": "sphere", "radius": -50}, "material": {"glass": "N-BK7"}}]})",
                                    "lens", "", {.require_camera = false});
    expect_all_in_view(scene);
}

TEST(FramingCamera, AnEmptySceneLooksAtTheOrigin) {
    const Scene scene = parse_scene(R"({"objects": []})", "empty", "", {.require_camera = false});
    const CameraSettings camera = camera_from_json(framing_camera_json(scene));
    EXPECT_NEAR(dot(camera.direction, normalize(Vec3{0, 0, 0} - camera.position)), 1.0, 1e-12);
}

}  // namespace
}  // namespace lenslab
