#pragma once
// Irradiance that reaches a point straight from the light sources, through shadow rays.
// Shared by every integrator that computes direct light explicitly.

#include "math/rng.h"
#include "optics/spectrum.h"
#include "scene/scene.h"

namespace lenslab {

// Spectral irradiance at the wavelengths `w` on a surface at `p` with unit normal `n` facing
// the side being lit. Emitting spheres are sampled uniformly in the cone they subtend
// (`samples` shadow rays each); point lights and beams are exact. Any object blocks light:
// light that passes through glass arrives as caustics, which need photon maps.
SampledSpectrum direct_irradiance(const Scene& scene, const Vec3& p, const Vec3& n, int samples,
                                  const SampledWavelengths& w, Rng& rng);

}  // namespace lenslab
