#pragma once
// Which lights a shaded point asks for direct light (pbrt-v4's LightSampler). A scene with a
// few lights asks every one of them, so the choice adds no noise; with many, one light is
// picked per shaded point in proportion to its power and its light divided by that
// probability, so the cost stays that of one light.

#include <vector>

#include "math/rng.h"
#include "scene/light_source.h"

namespace lenslab {

class LightSampler {
public:
    // Scenes with at most this many lights ask them all.
    static constexpr size_t kAskAllUpTo = 8;

    LightSampler() = default;
    explicit LightSampler(const std::vector<LightPtr>& lights);

    // Calls visit(light, weight) for the lights to ask: each with weight 1, or one chosen
    // light with weight 1 / (its probability).
    template <class Visit>
    void for_each(Rng& rng, Visit&& visit) const {
        if (m_lights.size() <= kAskAllUpTo) {
            for (const LightPtr& l : m_lights) visit(*l, 1.0);
            return;
        }
        double probability;
        const Light& l = pick(rng.uniform(), probability);
        visit(l, 1.0 / probability);
    }

    // The light whose share of the total power holds u, and that share.
    const Light& pick(double u, double& probability) const;

private:
    std::vector<LightPtr> m_lights;
    std::vector<double> m_cdf;  // running share of the power, ending at 1
};

}  // namespace lenslab
