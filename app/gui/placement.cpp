#include "placement.h"

#include <cmath>
#include <limits>

namespace lenslab::gui {

std::optional<Vec3> resting_offset(const Scene& scene, const Aabb& box, const Ray& ray,
                                   int ignore) {
    if (box.empty()) return std::nullopt;
    SceneHit hit;
    double t_min = 0;
    bool found = false;
    // Through the ignored entry's own surfaces (a few: a lens has three).
    for (int step = 0; step < 64; ++step) {
        if (!scene.intersect(ray, t_min, std::numeric_limits<double>::infinity(), hit)) break;
        if (scene.objects[hit.object].source != ignore || ignore < 0) {
            found = true;
            break;
        }
        t_min = hit.surface.t * (1 + 1e-9) + 1e-12;
    }
    if (!found) return std::nullopt;
    Vec3 n = hit.surface.normal;
    if (dot(n, ray.direction) > 0) n = -n;  // the side the eye sees
    const Vec3 e = box.extent();
    const double half = 0.5 * (std::abs(e.x * n.x) + std::abs(e.y * n.y) + std::abs(e.z * n.z));
    return hit.surface.point + n * half - box.centre();
}

Aabb entry_bounds(const Scene& scene, int source) {
    Aabb box;
    for (const SceneObject& o : scene.objects) {
        if (o.source != source || !o.shape) continue;
        const Aabb b = o.shape->bounds();
        box.expand(b.lo);
        box.expand(b.hi);
    }
    return box;
}

}  // namespace lenslab::gui
