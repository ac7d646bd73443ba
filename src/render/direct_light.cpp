#include "render/direct_light.h"

namespace lenslab {

void for_each_direct_light(const Scene& scene, const Vec3& p, const Vec3& n, int samples, Rng& rng,
                           const DirectLightSink& add) {
    const double eps = surface_epsilon(p);
    scene.light_sampler().for_each(rng, [&](const Light& light, double weight) {
        // A point or a beam is exact in one sample; an area light takes `samples`.
        const int count = light.is_delta() ? 1 : samples;
        double sum = 0.0;
        for (int s = 0; s < count; ++s) {
            LightSample ls;
            if (!light.sample_li(p, rng, ls)) continue;
            const double cos_n = dot(n, ls.wi);
            if (cos_n <= 0.0 || scene.occluded({p, ls.wi}, eps, ls.distance - eps)) continue;
            sum += ls.factor * cos_n;
        }
        if (sum > 0.0) add(light.spectrum(), sum * weight / count);
    });
}

SampledSpectrum direct_irradiance(const Scene& scene, const Vec3& p, const Vec3& n, int samples,
                                  const SampledWavelengths& w, Rng& rng) {
    SampledSpectrum e;
    for_each_direct_light(scene, p, n, samples, rng,
                          [&](const Spectrum& s, double factor) { e += s.sample(w) * factor; });
    return e;
}

}  // namespace lenslab
