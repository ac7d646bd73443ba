#include "scene/segment_medium.h"

namespace lenslab {

namespace {

const Medium* unless_clear(const Medium* m) { return m && !m->is_clear() ? m : nullptr; }

const Medium* atmosphere_of(const Scene& scene) {
    return unless_clear(scene.atmosphere ? &*scene.atmosphere : nullptr);
}

}  // namespace

const Medium* medium_at(const Scene& scene, const Vec3& point) {
    for (int i : scene.medium_solids()) {
        const SceneObject& o = scene.objects[static_cast<size_t>(i)];
        if (o.shape->contains(point)) return unless_clear(&*o.medium);
    }
    return atmosphere_of(scene);
}

const Medium* segment_medium(const Scene& scene, const Ray& ray, const Interaction* hit) {
    if (!hit) return atmosphere_of(scene);
    const SceneObject& o = *hit->object;
    if (o.shape->is_closed() && dot(ray.direction, hit->normal()) >= 0.0) {
        return o.medium ? unless_clear(&*o.medium) : nullptr;
    }
    if (scene.medium_solids().empty()) return atmosphere_of(scene);
    // Between two surfaces no boundary is crossed: the middle is as inside as any point.
    return medium_at(scene, ray.at(0.5 * hit->hit.surface.t));
}

}  // namespace lenslab
