#include "render/medium_transport.h"

#include <algorithm>
#include <cmath>

#include "optics/phase_function.h"
#include "render/density_tracking.h"
#include "scene/segment_medium.h"

namespace lenslab {

FreeFlight sample_free_flight(const Medium& medium, double t_max, Rng& rng) {
    const BandWeights sigma_t = medium.extinction();
    if (medium.scattering == BandWeights{0, 0, 0}) {
        // Nothing scatters: every path passes, carrying exactly Beer–Lambert's fraction.
        FreeFlight out;
        for (int b = 0; b < 3; ++b)
            out.weight[b] = sigma_t[b] > 0 ? std::exp(-sigma_t[b] * t_max) : 1.0;
        return out;
    }
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

namespace {

bool is_dark(const BandWeights& w) { return w == BandWeights{0, 0, 0}; }

FreeFlight heterogeneous_free_flight(const Medium& medium, const Ray& ray, double t_max, Rng& rng) {
    FreeFlight out;
    if (medium.scattering == BandWeights{0, 0, 0}) {
        out.weight = ratio_track(medium, ray, t_max, rng);
        return out;
    }
    const MediumDensity& density = *medium.density;
    const BandWeights mu = medium.extinction();
    const double mu_max = std::max({mu[0], mu[1], mu[2]});
    const double mu_mean = (mu[0] + mu[1] + mu[2]) / 3;
    const double majorant = mu_max * density.bound();
    for_each_tentative(density, majorant, ray, t_max, rng, [&](double t, double ft) {
        // P(real) = mean_b sigma_t,b(x) / majorant = mu_mean f / (mu_max bound).
        const double real = mu_mean * ft / majorant;
        if (rng.uniform() < real) {
            out.scattered = true;
            out.t = t;
            // sigma_s,b(x) / (majorant P): f cancels.
            for (int b = 0; b < 3; ++b) out.weight[b] *= medium.scattering[b] / mu_mean;
            return false;
        }
        for (int b = 0; b < 3; ++b)
            out.weight[b] *= (majorant - mu[b] * ft) / (majorant - mu_mean * ft);
        return true;
    });
    return out;
}

// Along one stretch of a shadow ray or a camera segment.
BandWeights stretch_transmittance(const Medium& medium, const Ray& ray, double length, Rng& rng) {
    return medium.is_heterogeneous() ? ratio_track(medium, ray, length, rng)
                                     : medium.transmittance(length);
}

}  // namespace

FreeFlight sample_free_flight(const Medium& medium, const Ray& ray, double t_max, Rng& rng) {
    return medium.is_heterogeneous() ? heterogeneous_free_flight(medium, ray, t_max, rng)
                                     : sample_free_flight(medium, t_max, rng);
}

BandWeights shadow_transmittance(const Scene& scene, const Vec3& p, const Vec3& wi, double distance,
                                 Rng& rng) {
    const double eps = surface_epsilon(p);
    if (scene.occluded({p, wi}, eps, distance - eps)) return {0, 0, 0};
    if (scene.medium_solids().empty()) {
        return scene.atmosphere ? stretch_transmittance(*scene.atmosphere, {p, wi}, distance, rng)
                                : BandWeights{1, 1, 1};
    }
    // Nothing blocks the way: every surface left on it is a medium's boundary, crossed one
    // segment at a time.
    const double end_eps = surface_epsilon(p + wi * distance);
    BandWeights tr{1, 1, 1};
    Ray ray{p, wi};
    double left = distance;
    for (;;) {
        Interaction it;
        const bool hit = scene.intersect(ray, surface_epsilon(ray.origin), left - end_eps, it.hit);
        if (hit) {
            it.object = &scene.objects[static_cast<size_t>(it.hit.object)];
            it.material = &scene.material_of(it.hit.object);
        }
        const double length = hit ? it.hit.surface.t : left;
        const Medium* medium =
            hit ? segment_medium(scene, ray, &it) : medium_at(scene, ray.at(0.5 * length));
        if (medium) {
            const BandWeights m = stretch_transmittance(*medium, ray, length, rng);
            for (int b = 0; b < 3; ++b) tr[b] *= m[b];
        }
        if (!hit) return tr;
        ray.origin = it.point();
        left -= length;
    }
}

void add_direct_light(const Scene& scene, const Vec3& p, int samples, Rng& rng,
                      const std::function<double(const Vec3& wi)>& angular, LightSum& e) {
    scene.light_sampler().for_each(rng, [&](const Light& light, double weight) {
        // A point or a beam is exact in one sample; an area light takes `samples`.
        const int count = light.is_delta() ? 1 : samples;
        for (int s = 0; s < count; ++s) {
            LightSample ls;
            if (!light.sample_li(p, rng, ls)) continue;
            const double a = angular(ls.wi);
            if (a <= 0.0) continue;
            const BandWeights tr = shadow_transmittance(scene, p, ls.wi, ls.distance, rng);
            if (is_dark(tr)) continue;
            e.add(light.spectrum(), ls.factor * a * weight / count, tr);
        }
    });
}

void add_light_in_scattering(const Scene& scene, const Medium& medium, const Ray& ray, double t_max,
                             int samples, Rng& rng, LightSum& e) {
    const HenyeyGreenstein phase(medium.g);
    for (const LightPtr& light : scene.lights()) {
        if (!light->samples_in_scattering()) continue;
        const int count = light->is_delta() ? 1 : samples;
        for (int s = 0; s < count; ++s) {
            double t, pdf;
            if (!light->sample_in_scattering(ray, t_max, rng.uniform(), t, pdf)) continue;
            const Vec3 p = ray.at(t);
            LightSample ls;
            if (!light->sample_li(p, rng, ls)) continue;
            // sigma_s at p: a heterogeneous medium's density there (0: nothing scatters).
            const double density = medium.is_heterogeneous() ? medium.density->local()(p) : 1.0;
            if (density == 0) continue;
            const BandWeights from_light = shadow_transmittance(scene, p, ls.wi, ls.distance, rng);
            if (is_dark(from_light)) continue;
            const BandWeights to_camera = stretch_transmittance(medium, ray, t, rng);
            BandWeights bands;
            for (int b = 0; b < 3; ++b)
                bands[b] = medium.scattering[b] * density * to_camera[b] * from_light[b];
            e.add(light->spectrum(),
                  ls.factor * phase.eval(dot(ls.wi, ray.direction)) / (pdf * count), bands);
        }
    }
}

}  // namespace lenslab
