#include "scene/segment_medium.h"

namespace lenslab {

const Medium* segment_medium(const Scene& scene, const Ray& ray, const Interaction* hit) {
    const bool inside_solid = hit && dot(ray.direction, hit->normal()) >= 0.0;
    if (inside_solid) return nullptr;  // solids hold no medium yet
    return scene.atmosphere ? &*scene.atmosphere : nullptr;
}

bool has_media(const Scene& scene) { return scene.atmosphere.has_value(); }

}  // namespace lenslab
