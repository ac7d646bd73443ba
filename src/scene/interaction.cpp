#include "scene/interaction.h"

#include <cmath>
#include <limits>

namespace lenslab {

bool next_interaction(const Scene& scene, const Ray& ray, double lambda_nm, Interaction& out) {
    if (!scene.intersect(ray, surface_epsilon(ray.origin), std::numeric_limits<double>::infinity(),
                         out.hit)) {
        return false;
    }
    out.object = &scene.objects[out.hit.object];
    out.material = &scene.materials[out.object->material];
    out.beyond = scene.medium_beyond(out.hit.object, out.point(), out.normal());
    out.scattering = scatter_at(out, ray.direction, lambda_nm);
    return true;
}

const Absorption* absorption_before(const Interaction& it, const Vec3& d) {
    const Absorption* own = it.material->absorption.get();
    const Absorption* other = it.beyond ? it.beyond->absorption.get() : nullptr;
    if (!own && !other) return nullptr;
    if (!it.object->shape->is_closed() || !(it.material->transparency > 0.0)) return nullptr;
    // Arriving from inside the solid: its glass; from outside: the neighbour's, if cemented.
    return dot(d, it.normal()) > 0.0 ? own : other;
}

double segment_transmittance(const Interaction& it, const Vec3& d, double lambda_nm) {
    const Absorption* a = absorption_before(it, d);
    // t is in units of |d|: a distance for the renderer's unit directions, kept exact for any.
    return a ? a->transmittance(lambda_nm, it.hit.surface.t * std::sqrt(dot(d, d))) : 1.0;
}

Scattering scatter_at(const Interaction& it, const Vec3& d, double lambda_nm) {
    return scatter(*it.material, it.object->shape->is_closed(), d, it.normal(), lambda_nm,
                   it.beyond);
}

}  // namespace lenslab
