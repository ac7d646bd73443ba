#pragma once
// Where photons start, shared by the photon-map tracer, sppm and detectors so all emit the
// same way. Two streams leave each light:
//   - emitted photons, sampled as the light emits (uniform directions for a point light);
//   - aimed photons, sampled only towards the photon targets (scene/photon_targets.h), so
//     that nearly every one of them reaches the glass and makes a caustic.
// Each stream divides its photons among the lights in proportion to their power, so every
// photon of a stream carries about the same power. A light sends aimed photons only where
// aiming is denser than its own sampling (Light::worth_aiming). For such a light a photon of
// either stream counts only in its part of the light's emission: an aimed photon only if the
// first object it meets is a target, an emitted one only if it is not (`counts`), which keeps
// every estimate unbiased. Without targets, or with aiming off, there are only emitted photons.

#include <cstdint>
#include <vector>

#include "math/halton.h"
#include "math/rng.h"
#include "scene/light_source.h"
#include "scene/scene.h"

namespace lenslab {

// Number of light sources that emit photons: emitting spheres, point lights, beams.
int photon_light_count(const Scene& scene);

// Light `light` counts emitting spheres first, then point lights, then beams.
const Spectrum& emitted_spectrum(const Scene& scene, int light);

class PhotonPlan {
public:
    // `emitted_per_light` and `aimed_per_light` photons per light on average in each stream;
    // `seed` rotates the stratified points aimed photons are drawn from (a new seed, a new
    // set of photons).
    PhotonPlan(const Scene& scene, int64_t emitted_per_light, int64_t aimed_per_light, bool aim,
               uint64_t seed);

    // All photons of both streams; photon `index` is in [0, total()).
    int64_t total() const { return m_total; }
    int64_t emitted_total() const { return m_stream_total[0]; }
    int64_t aimed_total() const { return m_stream_total[1]; }
    bool aiming() const { return m_aiming; }

    struct Photon {
        int light = 0;
        bool aimed = false;
        PhotonStart start;  // scale already divided by the photons its light sends in its stream
        // Aimed: where its wavelength lies in its light's spectrum, should it disperse (the
        // Halton point's last coordinate, so photons that land close together, coming from
        // nearby points, have wavelengths spread evenly over the spectrum); < 0: at random.
        double wavelength_u = -1;
    };
    // Samples photon `index` with `rng` (the caller seeds one stream per photon).
    Photon start(const Scene& scene, int64_t index, Rng& rng) const;

    // Whether a photon of `light` from the given stream, whose first hit is `object`, counts.
    bool counts(const Scene& scene, int light, bool aimed, int object) const {
        return !m_light_aims[static_cast<size_t>(light)] || aimed == scene.is_photon_target(object);
    }

private:
    struct Range {
        int64_t first, count;
        int light;
        bool aimed;
        std::array<double, kHaltonDimensions> rotation;  // of the Halton points aimed photons take
    };
    std::vector<Range> m_ranges;     // in photon order: emitted stream light by light, then aimed
    std::vector<char> m_light_aims;  // per light: it sends an aimed stream
    int64_t m_total = 0;
    int64_t m_stream_total[2] = {0, 0};
    bool m_aiming = false;
};

// Photons per light when `per_light` are asked for on average: their total divided in
// proportion to the lights' powers, but at least a quarter of an equal share each.
std::vector<int64_t> photons_by_power(const Scene& scene, int64_t per_light);

}  // namespace lenslab
