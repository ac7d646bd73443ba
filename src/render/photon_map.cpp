#include "render/photon_map.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace lenslab {

PhotonMap::PhotonMap(std::unique_ptr<Photon[]> direct, size_t direct_count,
                     std::unique_ptr<Photon[]> caustic, size_t caustic_count)
    : m_direct_storage(std::move(direct)), m_caustic_storage(std::move(caustic)) {
    tbb::parallel_invoke([&] { m_direct = PhotonKdTree(m_direct_storage.get(), direct_count); },
                         [&] { m_caustic = PhotonKdTree(m_caustic_storage.get(), caustic_count); });
}

Rgb PhotonMap::irradiance(const PhotonKdTree& map, const Vec3& x, const Vec3& n,
                          const GatherSettings& g, std::vector<PhotonNeighbour>& scratch) {
    const double r2 = map.nearest(x, g.radius, g.max_photons, &n, scratch);
    if (scratch.empty() || r2 <= 0.0) return {};
    const double r = std::sqrt(r2);
    double sum[3] = {0, 0, 0};
    double norm = 1.0;
    // Gaussian filter constants (Jensen 2001, eq. 7.7, after Pavicic 1990).
    constexpr double kAlpha = 0.918, kBeta = 1.953;
    const double gauss_denominator = 1.0 - std::exp(-kBeta);
    for (const PhotonNeighbour& nb : scratch) {
        double w = 1.0;
        if (g.filter == PhotonFilter::Cone) {
            w = 1.0 - std::sqrt(static_cast<double>(nb.dist2)) / (g.cone_k * r);
        } else if (g.filter == PhotonFilter::Gaussian) {
            w = kAlpha *
                (1.0 - (1.0 - std::exp(-kBeta * nb.dist2 / (2.0 * r2))) / gauss_denominator);
        }
        for (int c = 0; c < 3; ++c) sum[c] += w * nb.photon->power[c];
    }
    if (g.filter == PhotonFilter::Cone) norm = 1.0 - 2.0 / (3.0 * g.cone_k);
    const double scale = 1.0 / (norm * std::numbers::pi * r2);
    return {sum[0] * scale, sum[1] * scale, sum[2] * scale};
}

}  // namespace lenslab
