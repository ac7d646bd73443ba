#include "scene/framing_camera.h"

#include <cmath>
#include <numbers>

namespace lenslab {

nlohmann::json framing_camera_json(const Scene& scene) {
    constexpr double kFovDeg = 40;
    const Aabb b = scene.bounds();
    Vec3 centre{0, 0, 0};
    double radius = 1;
    if (!b.empty()) {
        centre = (b.lo + b.hi) * 0.5;
        radius = std::max(0.5 * length(b.extent()), 1e-6);
    }
    // Far enough that the bounding sphere fits the vertical field with a margin; lenses lie
    // along z in lens files, so the view is from the side, a little above and in front.
    const double distance = 1.15 * radius / std::sin(0.5 * kFovDeg * std::numbers::pi / 180);
    const Vec3 eye = centre + normalize(Vec3{1.0, 0.5, -0.8}) * distance;
    return {{"position", {eye.x, eye.y, eye.z}},
            {"look_at", {centre.x, centre.y, centre.z}},
            {"fov", kFovDeg}};
}

}  // namespace lenslab
