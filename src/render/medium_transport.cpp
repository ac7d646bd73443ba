#include "render/medium_transport.h"

#include <cmath>

#include "optics/phase_function.h"

namespace lenslab {

FreeFlight sample_free_flight(const Medium& medium, double t_max, Rng& rng) {
    const BandWeights sigma_t = medium.extinction();
    const int band = std::min(2, static_cast<int>(rng.uniform() * 3));
    const double u = rng.uniform();
    const double t = sigma_t[band] > 0 ? -std::log1p(-u) / sigma_t[band] : INFINITY;
    FreeFlight out;
    if (t < t_max) {
        // density(t) = mean over the bands of sigma_t exp(-sigma_t t).
        const BandWeights tr = medium.transmittance(t);
        double density = 0;
        for (int b = 0; b < 3; ++b) density += sigma_t[b] * tr[b] / 3;
        out.scattered = true;
        out.t = t;
        for (int b = 0; b < 3; ++b) out.weight[b] = medium.scattering[b] * tr[b] / density;
        return out;
    }
    // P(pass) = mean over the bands of exp(-sigma_t t_max) (1 where a band is clear).
    BandWeights tr{};
    double pass = 0;
    for (int b = 0; b < 3; ++b) {
        tr[b] = sigma_t[b] > 0 ? std::exp(-sigma_t[b] * t_max) : 1.0;
        pass += tr[b] / 3;
    }
    for (int b = 0; b < 3; ++b) out.weight[b] = tr[b] / pass;
    return out;
}

void add_direct_light(const Scene& scene, const Medium* medium, const Vec3& p, int samples,
                      Rng& rng, const std::function<double(const Vec3& wi)>& angular, LightSum& e,
                      bool delta_lights) {
    const double eps = surface_epsilon(p);
    scene.light_sampler().for_each(rng, [&](const Light& light, double weight) {
        if (!delta_lights && light.is_delta()) return;
        // A point or a beam is exact in one sample; an area light takes `samples`.
        const int count = light.is_delta() ? 1 : samples;
        for (int s = 0; s < count; ++s) {
            LightSample ls;
            if (!light.sample_li(p, rng, ls)) continue;
            const double a = angular(ls.wi);
            if (a <= 0.0 || scene.occluded({p, ls.wi}, eps, ls.distance - eps)) continue;
            const BandWeights tr =
                medium ? medium->transmittance(ls.distance) : BandWeights{1, 1, 1};
            e.add(light.spectrum(), ls.factor * a * weight / count, tr);
        }
    });
}

void add_delta_in_scattering(const Scene& scene, const Medium& medium, const Ray& ray, double t_max,
                             Rng& rng, LightSum& e) {
    const HenyeyGreenstein phase(medium.g);
    for (const LightPtr& light : scene.lights()) {
        if (!light->is_delta()) continue;
        double t, pdf;
        if (!light->sample_in_scattering(ray, t_max, rng.uniform(), t, pdf)) continue;
        const Vec3 p = ray.at(t);
        LightSample ls;
        if (!light->sample_li(p, rng, ls)) continue;
        const double eps = surface_epsilon(p);
        if (scene.occluded({p, ls.wi}, eps, ls.distance - eps)) continue;
        const BandWeights to_camera = medium.transmittance(t);
        const BandWeights from_light = medium.transmittance(ls.distance);
        BandWeights bands;
        for (int b = 0; b < 3; ++b) bands[b] = medium.scattering[b] * to_camera[b] * from_light[b];
        e.add(light->spectrum(), ls.factor * phase.eval(dot(ls.wi, ray.direction)) / pdf, bands);
    }
}

}  // namespace lenslab
