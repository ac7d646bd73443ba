#pragma once
// The photon maps: the direct map (L D) and the caustic map (L S+ D), each a block of stored
// photons with its kd-tree, and the radiance estimate that reads them.

#include <memory>
#include <string>
#include <vector>

#include "accel/photon_kdtree.h"
#include "scene/render_settings.h"  // PhotonFilter

namespace lenslab {

struct GatherSettings {
    double radius = 0.05;      // largest gather radius
    size_t max_photons = 500;  // cap on photons per estimate (k nearest within the radius)
    PhotonFilter filter = PhotonFilter::Cone;
    double cone_k = 1.1;  // cone filter constant, >= 1
};

class PhotonMap {
public:
    PhotonMap() = default;
    // Takes the `direct_count` direct photons and the `caustic_count` caustic ones and builds
    // both kd-trees.
    PhotonMap(std::unique_ptr<Photon[]> direct, size_t direct_count,
              std::unique_ptr<Photon[]> caustic, size_t caustic_count);
    PhotonMap(PhotonMap&&) = default;
    PhotonMap& operator=(PhotonMap&&) = default;

    const PhotonKdTree& direct() const { return m_direct; }
    const PhotonKdTree& caustic() const { return m_caustic; }
    size_t memory_bytes() const {
        return (m_direct.size() + m_caustic.size()) * sizeof(Photon) + m_direct.memory_bytes() +
               m_caustic.memory_bytes();
    }

    // Irradiance (W/m^2 per channel) at `x` on a surface whose normal `n` faces the side
    // being lit, from the photons of `map` that arrived on that side:
    //   E = sum_p w_p Phi_p / (norm * pi r^2),
    // with the cone filter w = 1 - d / (k r), norm = 1 - 2 / (3k), or the Gaussian filter.
    // `scratch` is reused between calls to avoid allocations.
    static Rgb irradiance(const PhotonKdTree& map, const Vec3& x, const Vec3& n,
                          const GatherSettings& g, std::vector<PhotonNeighbour>& scratch);

private:
    std::unique_ptr<Photon[]> m_direct_storage, m_caustic_storage;
    PhotonKdTree m_direct, m_caustic;
};

}  // namespace lenslab
