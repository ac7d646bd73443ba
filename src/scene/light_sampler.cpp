#include "scene/light_sampler.h"

#include <algorithm>

namespace lenslab {

LightSampler::LightSampler(const std::vector<LightPtr>& lights) : m_lights(lights) {
    double total = 0;
    for (const LightPtr& l : m_lights) total += l->power();
    double running = 0;
    for (const LightPtr& l : m_lights) {
        running += total > 0 ? l->power() / total : 1.0 / static_cast<double>(m_lights.size());
        m_cdf.push_back(running);
    }
    if (!m_cdf.empty()) m_cdf.back() = 1.0;
}

const Light& LightSampler::pick(double u, double& probability) const {
    const size_t i = std::min(
        static_cast<size_t>(std::upper_bound(m_cdf.begin(), m_cdf.end(), u) - m_cdf.begin()),
        m_lights.size() - 1);
    probability = m_cdf[i] - (i > 0 ? m_cdf[i - 1] : 0.0);
    return *m_lights[i];
}

}  // namespace lenslab
