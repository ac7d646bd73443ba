#include "render/integrators/path.h"

#include <numbers>
#include <stdexcept>

#include "math/rng.h"
#include "optics/phase_function.h"
#include "render/direct_light.h"
#include "render/medium_transport.h"
#include "render/path_colour.h"
#include "scene/interaction.h"
#include "scene/segment_medium.h"

namespace lenslab {

PathIntegrator::PathIntegrator(const Scene& scene) : PixelIntegrator(scene) {
    if (!scene.render.ambient.is_black()) m_ambient = illuminant_from_rgb(scene.render.ambient);
    if (!scene.render.background.is_black())
        m_background = illuminant_from_rgb(scene.render.background);
    // radiance() adds no direct light at free-flight scattering points: a light that media
    // did not gather along whole segments would be missing from them.
    if (scene.has_media()) {
        for (const LightPtr& light : scene.lights()) {
            if (!light->samples_in_scattering())
                throw std::logic_error("path: a light that media do not gather along segments");
        }
    }
}

// Paths follow the hero wavelength (no split: a path tracer's one path per sample).
Rgb PathIntegrator::radiance(const Ray& camera_ray, const SampledWavelengths& w,
                             const DispersionSplit* /*split*/, Rng& rng) const {
    const Scene& scene = m_scene;
    Rgb l;
    PathColour path(w);  // the throughput, and what the path still carries
    Ray ray = camera_ray;
    bool seen_from_camera = true;  // no diffuse bounce yet: the camera sees this chain
    bool count_emission = true;    // the last event was the camera or a specular one
    // Events so far: scatterings in media and at surfaces; crossing a medium's surfaceless
    // boundary is none.
    for (int bounce = 0;;) {
        Interaction it;
        // Refraction follows the hero wavelength (the others are dropped at a dispersive one).
        const bool hit = next_interaction(scene, ray, path.hero_nm(), it);
        const Medium* medium = segment_medium(scene, ray, hit ? &it : nullptr);
        if (medium) {
            const double t_max = hit ? it.hit.surface.t : INFINITY;
            if (bounce < scene.render.max_depth) {
                LightSum in_scattered(path);
                add_light_in_scattering(scene, *medium, ray, t_max, scene.render.light_samples, rng,
                                        in_scattered);
                l += path.of(in_scattered);
            }
            const FreeFlight f = sample_free_flight(*medium, ray, t_max, rng);
            path *= f.weight;
            if (f.scattered) {
                if (bounce >= scene.render.max_depth) break;
                // No direct light here: every light (points, spots, beams, spheres) is
                // gathered along the whole segment by add_light_in_scattering above.
                const Vec3 p = ray.at(f.t);
                const HenyeyGreenstein phase(medium->g);
                ray = {p, phase.sample(ray.direction, rng.uniform(), rng.uniform())};
                seen_from_camera = false;
                count_emission = false;
                ++bounce;
                continue;
            }
        }
        if (!hit) {
            if (seen_from_camera && m_background) l += path.of(*m_background);
            break;
        }
        if (absorption_before(it, ray.direction)) {
            // Beer-Lambert depends on wavelength: only the hero goes on, dimmed by it.
            path.disperse();
            path *= segment_transmittance(it, ray.direction, path.hero_nm());
        }
        if (it.scattering.dispersive) path.disperse();
        const Material& m = *it.material;
        const Vec3& p = it.point();
        if (m.surfaceless) {
            // Only a medium's edge: the path goes straight on, as if nothing were there.
            ray = {p, ray.direction};
            continue;
        }
        const Vec3& n = it.normal();
        const bool front_side = dot(ray.direction, n) < 0.0;
        const Vec3 facing = front_side ? n : -n;
        if (count_emission && front_side && m.is_emitter()) l += path.of(*m.emission);
        if (bounce >= scene.render.max_depth) break;

        const Scattering& s = it.scattering;
        const bool diffuse = s.diffuse > 0.0 && !m.color.is_black();
        if (diffuse) {
            LightSum e(path);
            if (scene.has_media()) {
                add_direct_light(
                    scene, p, scene.render.light_samples, rng,
                    [&](const Vec3& wi) { return dot(facing, wi); }, e);
            } else {
                for_each_direct_light(
                    scene, p, facing, scene.render.light_samples, rng,
                    [&](const Spectrum& light, double factor) { e.add(light, factor); });
            }
            e *= 1.0 / std::numbers::pi;
            if (seen_from_camera && m_ambient) e.add(*m_ambient, 1.0);
            PathColour reflected = path;
            reflected *= m.albedo_bands;
            l += reflected.of(e) * s.diffuse;
        }

        // One event, with the material's weights as probabilities. The diffuse bounce
        // survives with the albedo's largest component and carries albedo / that.
        const double survive = diffuse_continuation(s, m);
        const EventPick event = pick_event(s, survive, rng.uniform());
        if (event.diffuse) {
            path *= m.albedo_bands;
            path *= s.diffuse / survive;
            ray = {p, sample_diffuse_direction(facing, rng)};
            seen_from_camera = false;
            count_emission = false;
            ++bounce;
            continue;
        }
        if (!event.branch) break;  // absorbed
        ray = {p, event.branch->direction};
        count_emission = true;
        ++bounce;
    }
    return l;
}

}  // namespace lenslab
