#include "scene/interaction.h"

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

Scattering scatter_at(const Interaction& it, const Vec3& d, double lambda_nm) {
    return scatter(*it.material, it.object->shape->is_closed(), d, it.normal(), lambda_nm,
                   it.beyond);
}

}  // namespace lenslab
