#pragma once
// Recursive backward ray tracing with the report's illumination model:
//   I = ka Ia + sum_j Ij (N . Lj) + kr Ir + ks Is
// The diffuse part (weight 1 - transparency - specular, albedo `color`) takes ambient light
// and direct light from every source through shadow rays; the specular part follows the
// mirror ray and, at a dielectric, the Fresnel-weighted reflected and refracted rays, up to
// render.max_depth. Radiometry is physical: a Lambertian surface of albedo a under
// irradiance E has radiance a E / pi. Light through glass (caustics) needs photon maps.

#include "render/integrator.h"

namespace lenslab {

class WhittedIntegrator : public PixelIntegrator {
public:
    explicit WhittedIntegrator(const Scene& scene) : PixelIntegrator(scene) {}

protected:
    SampledSpectrum radiance(const Ray& ray, const SampledWavelengths& w, Rng& rng) const override;
    // Irradiance reaching a diffuse point `p` whose normal `n` faces the viewer: here the
    // direct light through shadow rays. The photon-map integrator adds caustics.
    virtual SampledSpectrum diffuse_irradiance(const Vec3& p, const Vec3& n, const SampledWavelengths& w,
                                               Rng& rng) const;

private:
    // `hero_only`: a dispersive refraction upstream already kept only the hero wavelength.
    SampledSpectrum trace(const Ray& ray, int depth, double weight, const SampledWavelengths& w,
                          bool hero_only, Rng& rng) const;
};

}  // namespace lenslab
