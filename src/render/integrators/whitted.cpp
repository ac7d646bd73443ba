#include "render/integrators/whitted.h"

#include <numbers>

#include "math/rng.h"
#include "render/direct_light.h"
#include "scene/interaction.h"

namespace lenslab {

Rgb WhittedIntegrator::radiance(const Ray& ray, Rng& rng) const { return trace(ray, 0, 1.0, rng); }

Rgb WhittedIntegrator::diffuse_irradiance(const Vec3& p, const Vec3& n, Rng& rng) const {
    return direct_irradiance(m_scene, p, n, m_scene.render.light_samples, rng);
}

Rgb WhittedIntegrator::trace(const Ray& ray, int depth, double weight, Rng& rng) const {
    const Scene& scene = m_scene;
    Interaction it;
    if (!next_interaction(scene, ray, it)) return scene.render.background;
    const Material& m = *it.material;
    const Vec3& p = it.point();
    const Vec3& n = it.normal();
    const bool front_side = dot(ray.direction, n) < 0.0;

    Rgb l;
    if (m.is_emitter() && front_side) l += m.emitted_radiance();

    const Scattering& s = it.scattering;
    if (s.diffuse > 0.0) {
        const Vec3 facing = front_side ? n : -n;
        const Rgb e = diffuse_irradiance(p, facing, rng);
        l += m.color * s.diffuse * (scene.render.ambient + e * (1.0 / std::numbers::pi));
    }
    if (depth >= scene.render.max_depth) return l;
    for (int i = 0; i < s.count; ++i) {
        const Branch& b = s.branches[i];
        if (weight * b.weight < scene.render.min_weight) continue;
        l += trace({p, b.direction}, depth + 1, weight * b.weight, rng) * b.weight;
    }
    return l;
}

}  // namespace lenslab
