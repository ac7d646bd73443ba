#pragma once
// Recursive backward ray tracing with the report's illumination model:
//   I = ka Ia + sum_j Ij (N . Lj) + kr Ir + ks Is
// The diffuse part (weight 1 - transparency - specular, albedo `color`) takes ambient light
// and direct light from every source through shadow rays; the specular part follows the
// mirror ray and, at a dielectric, the Fresnel-weighted reflected and refracted rays, up to
// render.max_depth. Radiometry is physical: a Lambertian surface of albedo a under
// irradiance E has radiance a E / pi. Light through glass (caustics) needs photon maps.
// Colour is exact on branches that met no dispersive refraction (render/path_colour.h).

#include "render/integrator.h"
#include "render/path_colour.h"

namespace lenslab {

class WhittedIntegrator : public PixelIntegrator {
public:
    explicit WhittedIntegrator(const Scene& scene);

protected:
    Rgb radiance(const Ray& ray, const SampledWavelengths& w, const DispersionSplit* split,
                 Rng& rng) const override;
    bool splits_at_dispersion() const override { return true; }
    // Adds the irradiance reaching a diffuse point `p` whose normal `n` faces the viewer: here
    // the direct light through shadow rays. The photon-map integrator adds caustics. `share`:
    // the part of the camera sample's colour this point's light makes (the branch weights
    // along the way, over the wavelengths of a split).
    virtual void add_diffuse_irradiance(LightSum& e, const Vec3& p, const Vec3& n, double share,
                                        Rng& rng) const;

private:
    // `path`: what the branch still carries (the hero wavelength alone once a dispersive
    // refraction upstream split the wavelengths); `weight`: its share of the sample's colour.
    Rgb trace(const Ray& ray, int depth, double weight, const PathColour& path, Rng& rng) const;
    // The refracted branches of a dispersive interaction `it` for each of the split's
    // wavelengths, the path arriving along `d` undispersed.
    Rgb trace_split(const struct Interaction& it, const Vec3& d, int depth, double weight,
                    const PathColour& path, Rng& rng) const;

    SpectrumPtr m_ambient, m_background;  // null when black
};

}  // namespace lenslab
