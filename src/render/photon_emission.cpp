#include "render/photon_emission.h"

#include <algorithm>
#include <cmath>

#include "math/halton.h"

namespace lenslab {

namespace {

// Streams of the Halton rotations, apart from the photons' own (2^62 + photon index).
constexpr uint64_t kEmissionRotationStream = (uint64_t{1} << 62) - (uint64_t{1} << 20);

}  // namespace

int photon_light_count(const Scene& scene) { return static_cast<int>(scene.lights().size()); }

const Spectrum& emitted_spectrum(const Scene& scene, int light) {
    return scene.lights()[static_cast<size_t>(light)]->spectrum();
}

std::vector<int64_t> photons_by_power(const Scene& scene, int64_t per_light) {
    const auto& lights = scene.lights();
    const double n = static_cast<double>(lights.size());
    double total_power = 0;
    for (const LightPtr& l : lights) total_power += l->power();
    // Shares by power, each at least a quarter of an equal share: a 1 W measuring beam
    // beside a 300 kW lamp still gets photons.
    std::vector<double> shares;
    double sum = 0;
    for (const LightPtr& l : lights) {
        shares.push_back(std::max(total_power > 0 ? l->power() / total_power : 0.0, 0.25 / n));
        sum += shares.back();
    }
    std::vector<int64_t> counts;
    const double budget = static_cast<double>(per_light) * n;
    for (const double share : shares) {
        counts.push_back(per_light <= 0 ? 0
                                        : std::max<int64_t>(1, std::llround(budget * share / sum)));
    }
    return counts;
}

PhotonPlan::PhotonPlan(const Scene& scene, int64_t emitted_per_light, int64_t aimed_per_light,
                       bool aim, uint64_t seed) {
    const bool aiming = aim && !scene.photon_targets().empty() && aimed_per_light > 0;
    for (const LightPtr& l : scene.lights()) {
        m_light_aims.push_back(aiming && l->worth_aiming(scene.photon_targets()));
        m_aiming = m_aiming || m_light_aims.back();
    }
    for (int stream = 0; stream < 2; ++stream) {
        if (stream == 1 && !m_aiming) break;
        const std::vector<int64_t> counts =
            photons_by_power(scene, stream == 0 ? emitted_per_light : aimed_per_light);
        for (size_t l = 0; l < counts.size(); ++l) {
            if (counts[l] == 0 || (stream == 1 && !m_light_aims[l])) continue;
            Range r{m_total, counts[l], static_cast<int>(l), stream == 1, {}};
            Rng rotation(seed, kEmissionRotationStream + l);
            for (double& x : r.rotation) x = rotation.uniform();
            m_ranges.push_back(r);
            m_total += counts[l];
            m_stream_total[stream] += counts[l];
        }
    }
}

PhotonPlan::Photon PhotonPlan::start(const Scene& scene, int64_t index, Rng& rng) const {
    // The last range starting at or before `index`.
    const auto it = std::upper_bound(m_ranges.begin(), m_ranges.end(), index,
                                     [](int64_t i, const Range& r) { return i < r.first; });
    const Range& r = *(it - 1);
    const Light& light = *scene.lights()[static_cast<size_t>(r.light)];
    // Aimed photons from consecutive Halton points: they spread evenly over the caustic. The
    // light takes the first coordinates, the wavelength the last.
    Photon p{r.light, r.aimed, {}};
    if (r.aimed) {
        const auto u = halton_point(static_cast<uint64_t>(index - r.first), r.rotation);
        AimSample aim;
        std::copy_n(u.begin(), aim.size(), aim.begin());
        p.start = light.sample_le_towards(scene.photon_targets(), aim);
        p.wavelength_u = u[kHaltonDimensions - 1];
    } else {
        p.start = light.sample_le(rng);
    }
    p.start.scale /= static_cast<double>(r.count);
    return p;
}

}  // namespace lenslab
