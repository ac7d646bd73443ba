#include "render/integrators/whitted.h"

#include <numbers>

#include "math/rng.h"
#include "render/direct_light.h"
#include "scene/interaction.h"

namespace lenslab {

WhittedIntegrator::WhittedIntegrator(const Scene& scene) : PixelIntegrator(scene) {
    if (!scene.render.ambient.is_black()) m_ambient = illuminant_from_rgb(scene.render.ambient);
    if (!scene.render.background.is_black())
        m_background = illuminant_from_rgb(scene.render.background);
}

Rgb WhittedIntegrator::radiance(const Ray& ray, const SampledWavelengths& w,
                                const DispersionSplit* split, Rng& rng) const {
    return trace(ray, 0, 1.0, PathColour(w, split), rng);
}

void WhittedIntegrator::add_diffuse_irradiance(LightSum& e, const Vec3& p, const Vec3& n,
                                               double /*share*/, Rng& rng) const {
    for_each_direct_light(m_scene, p, n, m_scene.render.light_samples, rng,
                          [&](const Spectrum& s, double factor) { e.add(s, factor); });
}

Rgb WhittedIntegrator::trace(const Ray& ray, int depth, double weight, const PathColour& arriving,
                             Rng& rng) const {
    const Scene& scene = m_scene;
    Interaction it;
    // Refraction follows the hero wavelength; the others ride along until a dispersive
    // refraction splits them off.
    if (!next_interaction(scene, ray, arriving.hero_nm(), it))
        return m_background ? arriving.of(*m_background) : Rgb{};
    PathColour path = arriving;
    if (absorption_before(it, ray.direction)) {
        // Beer-Lambert depends on wavelength: only the hero goes on, dimmed by it.
        path.disperse();
        path *= segment_transmittance(it, ray.direction, path.hero_nm());
    }
    const Material& m = *it.material;
    const Vec3& p = it.point();
    const Vec3& n = it.normal();
    const bool front_side = dot(ray.direction, n) < 0.0;

    Rgb l;
    if (m.is_emitter() && front_side) l += path.of(*m.emission);

    const Scattering& s = it.scattering;
    if (s.diffuse > 0.0) {
        LightSum e(path);
        add_diffuse_irradiance(e, p, front_side ? n : -n, weight, rng);
        e *= 1.0 / std::numbers::pi;
        if (m_ambient) e.add(*m_ambient, 1.0);
        PathColour reflected = path;
        reflected *= m.albedo_bands;
        l += reflected.of(e) * s.diffuse;
    }
    if (depth >= scene.render.max_depth) return l;
    // A weak branch is not split: its wavelengths follow one of them together (merge_weight).
    const bool split = s.dispersive && path.split() && weight >= scene.render.merge_weight;
    if (split) l += trace_split(it, ray.direction, depth, weight, path, rng);
    for (int i = 0; i < s.count; ++i) {
        const Branch& b = s.branches[i];
        double carried = weight * b.weight;
        PathColour next = path;
        // The wavelengths of a split whose branch here is weak in all (merge_weight) follow
        // one of them together, carrying the whole spectrum.
        if (const size_t count = path.split_count();
            count > 0 && carried * count < scene.render.merge_weight) {
            if (!path.carries_merged()) continue;
            next = path.merged();
            carried *= static_cast<double>(count);
        }
        if (carried < scene.render.min_weight) continue;
        if (s.dispersive && b.event == Event::Refract) {
            if (split) continue;
            if (path.split()) {
                next = path.merged_split();
            } else {
                next.disperse();
            }
        }
        l += trace({p, b.direction}, depth + 1, carried, next, rng) * b.weight;
    }
    return l;
}

Rgb WhittedIntegrator::trace_split(const Interaction& it, const Vec3& d, int depth, double weight,
                                   const PathColour& path, Rng& rng) const {
    Rgb l;
    const auto& split = path.split()->wavelengths();
    // Each wavelength carries its share of the colour (the split's weights are in the colour,
    // the branch weight multiplies the light).
    const double share = weight / static_cast<double>(split.size());
    for (size_t k = 0; k < split.size(); ++k) {
        // Each wavelength refracts with its own index.
        const Scattering s = scatter_at(it, d, split[k].nm);
        for (int i = 0; i < s.count; ++i) {
            const Branch& b = s.branches[i];
            if (b.event != Event::Refract || share * b.weight < m_scene.render.min_weight) continue;
            l += trace({it.point(), b.direction}, depth + 1, share * b.weight, path.split_to(k),
                       rng) *
                 b.weight;
        }
    }
    return l;
}

}  // namespace lenslab
