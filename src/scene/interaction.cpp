#include "scene/interaction.h"

#include <limits>

namespace lenslab {

bool next_interaction(const Scene& scene, const Ray& ray, double lambda_nm, Interaction& out) {
    if (!scene.intersect(ray, surface_epsilon(ray.origin), std::numeric_limits<double>::infinity(), out.hit)) {
        return false;
    }
    out.object = &scene.objects[out.hit.object];
    out.material = &scene.materials[out.object->material];
    out.scattering =
        scatter(*out.material, out.object->shape->is_closed(), ray.direction, out.normal(), lambda_nm);
    return true;
}

}  // namespace lenslab
