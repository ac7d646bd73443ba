#pragma once
// Irradiance that reaches a point straight from the light sources, through shadow rays.
// Shared by every integrator that computes direct light explicitly.

#include <functional>

#include "math/rng.h"
#include "optics/spectrum.h"
#include "scene/scene.h"

namespace lenslab {

// Each light's part of the irradiance: `factor` times the light's `spectrum`.
using DirectLightSink = std::function<void(const Spectrum& spectrum, double factor)>;

// The spectral irradiance on a surface at `p` with unit normal `n` facing the side being lit,
// light by light: the sum of what `add` receives. The scene's light sampler says which lights
// are asked (all of a few, one by power of many); each gives its light through
// Light::sample_li: emitting spheres sampled uniformly in the cone they subtend (`samples`
// shadow rays each), point lights and beams exactly. Any
// object blocks light: light that passes through glass arrives as caustics, which need
// photon maps. Callers take the spectra at their wavelengths or as band colours.
void for_each_direct_light(const Scene& scene, const Vec3& p, const Vec3& n, int samples, Rng& rng,
                           const DirectLightSink& add);

// That irradiance at the wavelengths `w`.
SampledSpectrum direct_irradiance(const Scene& scene, const Vec3& p, const Vec3& n, int samples,
                                  const SampledWavelengths& w, Rng& rng);

}  // namespace lenslab
