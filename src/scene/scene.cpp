#include "scene/scene.h"

namespace lenslab {

void Scene::build() {
    std::vector<const Shape*> shapes;
    shapes.reserve(objects.size());
    m_emitters.clear();
    for (size_t i = 0; i < objects.size(); ++i) {
        shapes.push_back(objects[i].shape.get());
        const Material& m = materials[objects[i].material];
        // The scene reader lets only spheres emit; other emitting shapes are not lights.
        const auto* sphere = dynamic_cast<const Sphere*>(objects[i].shape.get());
        if (m.is_emitter() && sphere) {
            m_emitters.push_back({static_cast<int>(i), sphere, m.emission});
        }
    }
    m_bvh = Bvh(std::move(shapes));
}

bool Scene::intersect(const Ray& ray, double t_min, double t_max, SceneHit& hit) const {
    BvhHit h;
    if (!m_bvh.intersect(ray, t_min, t_max, h)) return false;
    hit.surface = h.surface;
    hit.object = h.primitive;
    return true;
}

bool Scene::occluded(const Ray& ray, double t_min, double t_max) const {
    return m_bvh.occluded(ray, t_min, t_max);
}

}  // namespace lenslab
