#include "scene/scene.h"

#include <algorithm>

namespace lenslab {

void Scene::build() {
    std::vector<const Shape*> shapes;
    shapes.reserve(objects.size());
    m_emitters.clear();
    for (size_t i = 0; i < objects.size(); ++i) {
        shapes.push_back(objects[i].shape.get());
        const Material& m = materials[objects[i].material];
        // The scene reader lets only spheres emit; other emitting shapes are not lights.
        const std::optional<BoundingSphere> sphere = objects[i].shape->exact_sphere();
        if (m.is_emitter() && sphere) {
            m_emitters.push_back({static_cast<int>(i), *sphere, m.emission});
        }
    }
    m_bvh = Bvh(std::move(shapes));
    find_touching_solids();
    find_media();
    find_lights_and_targets();
}

void Scene::find_media() {
    m_medium_solids.clear();
    m_see_through.clear();
    for (size_t i = 0; i < objects.size(); ++i) {
        if (objects[i].medium) m_medium_solids.push_back(static_cast<int>(i));
        if (material_of(static_cast<int>(i)).surfaceless) {
            m_see_through.resize(objects.size(), 0);
            m_see_through[i] = 1;
        }
    }
    const auto volume = [this](int object) {
        const Aabb b = objects[static_cast<size_t>(object)].shape->bounds();
        return (b.hi.x - b.lo.x) * (b.hi.y - b.lo.y) * (b.hi.z - b.lo.z);
    };
    std::stable_sort(m_medium_solids.begin(), m_medium_solids.end(),
                     [&](int a, int b) { return volume(a) < volume(b); });
}

void Scene::set_lights(SceneLights lights) {
    point_lights = std::move(lights.points);
    beams = std::move(lights.beams);
    spots = std::move(lights.spots);
    area_lights = std::move(lights.areas);
    find_lights_and_targets();
}

void Scene::find_lights_and_targets() {
    m_lights.clear();
    for (const SphereEmitter& e : m_emitters) {
        m_lights.push_back(
            make_sphere_light(objects[static_cast<size_t>(e.object)].shape, e.sphere, e.radiance));
    }
    for (const PointLight& l : point_lights) m_lights.push_back(make_point_light(l));
    for (const BeamLight& b : beams) m_lights.push_back(make_beam_light(b));
    for (const SpotLight& s : spots) m_lights.push_back(make_spot_light(s));
    m_lights.insert(m_lights.end(), area_lights.begin(), area_lights.end());
    m_light_sampler = LightSampler(m_lights);

    std::vector<BoundingSphere> targets;
    m_is_target.assign(objects.size(), 0);
    m_specular_non_target = false;
    for (size_t i = 0; i < objects.size(); ++i) {
        const Material& m = material_of(static_cast<int>(i));
        const bool specular = m.transparency > 0.0 || m.specular > 0.0;
        const bool target = objects[i].photon_target.value_or(specular) && !m.is_emitter();
        if (target) {
            m_is_target[i] = 1;
            targets.push_back(objects[i].shape->bounding_sphere());
        } else if (specular) {
            m_specular_non_target = true;
        }
    }
    m_targets = PhotonTargets(std::move(targets));
}

namespace {

bool is_dielectric_solid(const SceneObject& o, const Material& m) {
    return o.shape->is_closed() && m.transparency > 0.0;
}

Aabb padded(Aabb b) {
    const double pad = surface_epsilon(b.hi) + surface_epsilon(b.lo);
    for (int a = 0; a < 3; ++a) {
        b.lo[a] -= pad;
        b.hi[a] += pad;
    }
    return b;
}

bool overlap(const Aabb& a, const Aabb& b) {
    for (int k = 0; k < 3; ++k) {
        if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
    }
    return true;
}

}  // namespace

// Pairs of transparent solids whose (padded) boxes overlap. Quadratic in the number of
// transparent solids, which scenes have few of; opaque objects and open surfaces never count.
void Scene::find_touching_solids() {
    m_touching.assign(objects.size(), {});
    std::vector<int> solids;
    for (size_t i = 0; i < objects.size(); ++i) {
        if (is_dielectric_solid(objects[i], material_of(static_cast<int>(i)))) {
            solids.push_back(static_cast<int>(i));
        }
    }
    for (size_t a = 0; a < solids.size(); ++a) {
        const Aabb box = padded(objects[solids[a]].shape->bounds());
        for (size_t b = a + 1; b < solids.size(); ++b) {
            if (overlap(box, padded(objects[solids[b]].shape->bounds()))) {
                m_touching[solids[a]].push_back(solids[b]);
                m_touching[solids[b]].push_back(solids[a]);
            }
        }
    }
}

const Material* Scene::medium_beyond(int object, const Vec3& point,
                                     const Vec3& outward_normal) const {
    const int other = solid_beyond(object, point, outward_normal);
    return other < 0 ? nullptr : &material_of(other);
}

int Scene::solid_beyond(int object, const Vec3& point, const Vec3& outward_normal) const {
    const std::vector<int>& candidates = m_touching[object];
    if (candidates.empty()) return -1;
    // Step just off the surface, to the side away from `object`: ten times the offset rays
    // use to leave a surface, far above the rounding of two solids' shared surface and far
    // below any air gap a scene means.
    const Vec3 probe = point + outward_normal * (10.0 * surface_epsilon(point));
    for (int other : candidates) {
        if (objects[other].shape->contains(probe)) return other;
    }
    return -1;
}

bool Scene::intersect(const Ray& ray, double t_min, double t_max, SceneHit& hit) const {
    BvhHit h;
    if (!m_bvh.intersect(ray, t_min, t_max, h)) return false;
    hit.surface = h.surface;
    hit.object = h.primitive;
    return true;
}

bool Scene::occluded(const Ray& ray, double t_min, double t_max) const {
    return m_bvh.occluded(ray, t_min, t_max, m_see_through.empty() ? nullptr : &m_see_through);
}

}  // namespace lenslab
