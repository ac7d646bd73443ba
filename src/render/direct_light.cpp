#include "render/direct_light.h"

#include <cmath>
#include <numbers>

#include "geometry/sphere.h"
#include "math/frame.h"
#include "math/sampling.h"

namespace lenslab {

namespace {

void from_point_light(const Scene& scene, const PointLight& l, const Vec3& p, const Vec3& n,
                      double eps, const DirectLightSink& add) {
    const Vec3 to_light = l.position - p;
    const double dist2 = length_squared(to_light);
    const double dist = std::sqrt(dist2);
    const Vec3 wi = to_light / dist;
    const double cos_n = dot(n, wi);
    if (cos_n <= 0.0 || scene.occluded({p, wi}, eps, dist - eps)) return;
    // E = I cos(theta) / r^2 with I = Phi / (4 pi) for an isotropic source.
    add(*l.spectrum, cos_n / (4.0 * std::numbers::pi * dist2));
}

void from_beam(const Scene& scene, const BeamLight& b, const Vec3& p, const Vec3& n, double eps,
               const DirectLightSink& add) {
    const Vec3 v = p - b.origin;
    const double along = dot(v, b.direction);
    if (along <= 0.0 || length_squared(v - b.direction * along) > b.radius * b.radius) return;
    const double cos_n = -dot(n, b.direction);
    if (cos_n <= 0.0 || scene.occluded({p, -b.direction}, eps, along - eps)) return;
    add(*b.spectrum, cos_n / (std::numbers::pi * b.radius * b.radius));
}

void from_sphere_emitter(const Scene& scene, const SphereEmitter& emitter, const Vec3& p,
                         const Vec3& n, int samples, Rng& rng, double eps,
                         const DirectLightSink& add) {
    const Sphere& sphere = *emitter.sphere;
    const Vec3 to_centre = sphere.centre() - p;
    const double d2 = length_squared(to_centre);
    const double r2 = sphere.radius() * sphere.radius();
    if (d2 <= r2) return;  // inside the light
    const double d = std::sqrt(d2);
    const double cos_max = std::sqrt(1.0 - r2 / d2);
    // 1 - cos_max written without cancellation for small, distant lights.
    const double one_minus_cos = (r2 / d2) / (1.0 + cos_max);
    const double inv_pdf = 2.0 * std::numbers::pi * one_minus_cos;
    const Frame frame = Frame::from_axis(to_centre / d);

    double sum = 0.0;
    for (int s = 0; s < samples; ++s) {
        const Vec3 wi = frame.to_world(sample_uniform_cone(rng.uniform(), rng.uniform(), cos_max));
        const double cos_n = dot(n, wi);
        if (cos_n <= 0.0) continue;
        SurfaceHit h;
        if (!sphere.intersect({p, wi}, eps, INFINITY, h)) continue;  // grazing the silhouette
        if (scene.occluded({p, wi}, eps, h.t - eps)) continue;
        sum += cos_n;
    }
    add(*emitter.radiance, sum * inv_pdf / samples);
}

}  // namespace

void for_each_direct_light(const Scene& scene, const Vec3& p, const Vec3& n, int samples, Rng& rng,
                           const DirectLightSink& add) {
    const double eps = surface_epsilon(p);
    for (const PointLight& l : scene.point_lights) from_point_light(scene, l, p, n, eps, add);
    for (const BeamLight& b : scene.beams) from_beam(scene, b, p, n, eps, add);
    for (const SphereEmitter& s : scene.emitters())
        from_sphere_emitter(scene, s, p, n, samples, rng, eps, add);
}

SampledSpectrum direct_irradiance(const Scene& scene, const Vec3& p, const Vec3& n, int samples,
                                  const SampledWavelengths& w, Rng& rng) {
    SampledSpectrum e;
    for_each_direct_light(scene, p, n, samples, rng,
                          [&](const Spectrum& s, double factor) { e += s.sample(w) * factor; });
    return e;
}

}  // namespace lenslab
