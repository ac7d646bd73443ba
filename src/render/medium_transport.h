#pragma once
// Light travelling through a participating medium (scene/medium.h), for the tracers: where
// it next scatters, the direct light that reaches a point through the medium, and the light
// of point lights, spots and beams scattered into a ray on its way.
//
// The medium's coefficients differ by band (spectrum.h), so one distance is drawn for all
// three: a band is picked at random and the distance drawn from its exponential, with the
// weights divided by the average density of the three (one-sample multiple importance
// sampling over the bands, as pbrt-v4 does over wavelengths). In a grey medium this is plain
// exponential free-flight sampling; in a coloured one no band's weight grows without bound.

#include <functional>

#include "math/rng.h"
#include "render/path_colour.h"
#include "scene/medium.h"
#include "scene/scene.h"

namespace lenslab {

struct FreeFlight {
    bool scattered = false;       // the light scattered before `t_max`
    double t = 0;                 // where, when it did
    BandWeights weight{1, 1, 1};  // what multiplies the throughput in each band
};

// Light leaving along a ray through a homogeneous `medium` with the next surface at `t_max`
// (INFINITY: none). Scattered: weight = sigma_s T(t) / density(t); passed: T(t_max) /
// P(pass). A medium that only absorbs is passed every time with weight T(t_max).
FreeFlight sample_free_flight(const Medium& medium, double t_max, Rng& rng);

// The same along `ray` through any medium. A heterogeneous one is crossed by delta tracking
// against the majorant of its densest band (render/density_tracking.h), weighted per band:
// at each tentative collision it is real with probability P = mean_b sigma_t,b(x) / majorant,
// a real one scatters with weights sigma_s,b(x) / (majorant P), a null one goes on with
// weights (majorant - sigma_t,b(x)) / (majorant (1 - P)) (the null-collision integral,
// Novák et al. 2018, section 5.1). In a grey medium a null collision weighs exactly 1 and a
// real one the albedo. A medium that only absorbs is passed every time with ratio
// tracking's estimate of T(t_max).
FreeFlight sample_free_flight(const Medium& medium, const Ray& ray, double t_max, Rng& rng);

// The fraction of light, per band, that goes from `p` the `distance` along `wi` (a shadow
// ray): 0 where a surface blocks it, else the product of the transmittances of the media it
// crosses (segment_medium's, piece by piece), passing through surfaceless boundaries: from
// inside a smoke box to a light outside, the box's smoke, then the air or the atmosphere.
// A heterogeneous medium's is estimated by ratio tracking with `rng` (unbiased).
BandWeights shadow_transmittance(const Scene& scene, const Vec3& p, const Vec3& wi, double distance,
                                 Rng& rng);

// The light reaching `p` straight from each light, attenuated by the media on the way
// (shadow_transmittance), each sample weighted by `angular(wi)` (wi towards the light): the
// cosine at a surface, the phase function at a point in a medium; <= 0 drops the sample.
// Added to `e` as the spectrum of each light times its weights.
void add_direct_light(const Scene& scene, const Vec3& p, int samples, Rng& rng,
                      const std::function<double(const Vec3& wi)>& angular, LightSum& e);

// The light of points, spots, beams and emitting spheres (Light::samples_in_scattering)
// scattered once into a ray's segment [0, t_max) in `medium`: distances from
// Light::sample_in_scattering (one per delta light, `samples` per sphere), weighted
// by sigma_s, the transmittance from the ray's origin and from the light (through whatever
// media lie between, shadow_transmittance), and the phase function. A laser a few millimetres wide
// is all but never met by free-flight scattering points; sampled along the chord the ray cuts
// through it, it shows at once. In a heterogeneous medium sigma_s is taken at each sampled
// point and the transmittance from the origin estimated by ratio tracking.
void add_light_in_scattering(const Scene& scene, const Medium& medium, const Ray& ray, double t_max,
                             int samples, Rng& rng, LightSum& e);

}  // namespace lenslab
