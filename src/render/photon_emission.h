#pragma once
// Where photons start: a point and direction on one light, and the share of the light's power
// the photon carries. Shared by the photon-map tracer and sppm so both emit the same way.

#include <cstdint>

#include "geometry/ray.h"
#include "math/rng.h"
#include "optics/spectrum.h"
#include "scene/scene.h"

namespace lenslab {

struct PhotonStart {
    Ray ray;
    const Spectrum* spectrum = nullptr;  // spectral flux of its light (W per nm, before `scale`)
    double scale = 0;  // this photon's share: the flux it carries is spectrum * scale
};

// Number of light sources that emit photons: emitting spheres, point lights, beams.
int photon_light_count(const Scene& scene);

// Light `light` counts emitting spheres first, then point lights, then beams.
const Spectrum& emitted_spectrum(const Scene& scene, int light);

// Samples one of `n` photons of light `light`: emitting spheres send cosine-distributed
// photons from uniform points on their surface (a Lambertian sphere of radiance L and radius
// R emits pi L 4 pi R^2), point lights uniform directions, beams uniform points on their disc.
PhotonStart emit_photon(const Scene& scene, int light, int64_t n, Rng& rng);

}  // namespace lenslab
