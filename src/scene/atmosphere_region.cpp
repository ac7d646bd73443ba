#include "scene/atmosphere_region.h"

#include "scene/scene.h"

namespace lenslab {

Aabb atmosphere_region(const Scene& scene) {
    Aabb box;
    for (const SceneObject& o : scene.objects) box.expand(o.shape->bounds());
    box.expand(scene.camera.position);
    for (const LightPtr& l : scene.lights()) box.expand(l->bounds());
    // A margin, relative with a floor, so a flat scene still has a volume and light at
    // its edges is inside.
    const Vec3 pad = Vec3{1, 1, 1} * (0.05 * length(box.extent()) + 1e-3);
    return {box.lo - pad, box.hi + pad};
}

}  // namespace lenslab
