#pragma once
// Unbiased path tracing: the reference the other integrators are checked against. Every
// camera sample follows one path, choosing at each surface one of the material's events
// with its weight as the probability (diffuse, mirror, Fresnel reflection or refraction;
// what is left is absorbed, which ends the path: Russian roulette by the material itself),
// and adds the direct light of emitting spheres, point lights and beams at every diffuse
// surface through shadow rays (next-event estimation). An emitting sphere a path meets is
// counted only when the path came from the camera or a specular event, since the shadow rays
// already counted the light a diffuse surface receives straight from it.
//
// What a path tracer cannot find: light from point lights and beams that reaches a diffuse
// surface through glass or off a mirror (a delta light seen through a delta event); those
// caustics need photons (photon_map, sppm). Emitting spheres' caustics converge, slowly.
//
// The report's ambient term is kept as it is in `whitted`: added where the camera, directly
// or through mirrors and glass, first sees a diffuse surface; `background` is what rays that
// leave the scene on such a chain see, not a light (so all integrators agree on both).
//
// The throughput of a path that met no dispersive refraction is a number times band-constant
// albedos, so its colour is exact (render/path_colour.h); a dispersive surface leaves the
// hero wavelength alone on the path.

#include "render/integrator.h"

namespace lenslab {

class PathIntegrator final : public PixelIntegrator {
public:
    explicit PathIntegrator(const Scene& scene);

protected:
    Rgb radiance(const Ray& ray, const SampledWavelengths& w, const DispersionSplit* split,
                 Rng& rng) const override;

private:
    SpectrumPtr m_ambient, m_background;  // null when black
};

}  // namespace lenslab
