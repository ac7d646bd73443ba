#include "render/integrators/whitted.h"

#include <numbers>

#include "math/rng.h"
#include "render/direct_light.h"
#include "scene/interaction.h"

namespace lenslab {

SampledSpectrum WhittedIntegrator::radiance(const Ray& ray, const SampledWavelengths& w, Rng& rng) const {
    return trace(ray, 0, 1.0, w, false, rng);
}

SampledSpectrum WhittedIntegrator::diffuse_irradiance(const Vec3& p, const Vec3& n, const SampledWavelengths& w,
                                                      Rng& rng) const {
    return direct_irradiance(m_scene, p, n, m_scene.render.light_samples, w, rng);
}

SampledSpectrum WhittedIntegrator::trace(const Ray& ray, int depth, double weight, const SampledWavelengths& w,
                                         bool hero_only, Rng& rng) const {
    const Scene& scene = m_scene;
    Interaction it;
    // Refraction follows the hero wavelength; the others ride along until a dispersive
    // refraction splits them off.
    if (!next_interaction(scene, ray, w.nm[0], it)) {
        return scene.render.background.is_black() ? SampledSpectrum{} : illuminant_from_rgb(scene.render.background, w);
    }
    const Material& m = *it.material;
    const Vec3& p = it.point();
    const Vec3& n = it.normal();
    const bool front_side = dot(ray.direction, n) < 0.0;

    SampledSpectrum l;
    if (m.is_emitter() && front_side) l += m.emission->sample(w);

    const Scattering& s = it.scattering;
    if (s.diffuse > 0.0) {
        const Vec3 facing = front_side ? n : -n;
        const SampledSpectrum e = diffuse_irradiance(p, facing, w, rng);
        // Most scenes have no ambient term: skip turning a black colour into a spectrum.
        const SampledSpectrum ambient =
            scene.render.ambient.is_black() ? SampledSpectrum{} : illuminant_from_rgb(scene.render.ambient, w);
        l += m.albedo->sample(w) * s.diffuse * (ambient + e * (1.0 / std::numbers::pi));
    }
    if (depth >= scene.render.max_depth) return l;
    for (int i = 0; i < s.count; ++i) {
        const Branch& b = s.branches[i];
        if (weight * b.weight < scene.render.min_weight) continue;
        const bool split = s.dispersive && b.event == Event::Refract && !hero_only;
        SampledSpectrum branch = trace({p, b.direction}, depth + 1, weight * b.weight, w, hero_only || split, rng);
        if (split) branch = branch.hero_only();
        l += branch * b.weight;
    }
    return l;
}

}  // namespace lenslab
