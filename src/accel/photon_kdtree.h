#pragma once
// Balanced kd-tree over photons, stored implicitly: each range [lo, hi) keeps its median
// photon at the middle index, splitting along the axis of the range's largest extent (the
// report cycled X, Y, Z; the widest axis gives tighter cells). No nodes, no indices: the
// photons themselves are reordered, so the tree costs nothing beyond the 32-byte photons.
// Queries are k-nearest within a radius (Jensen 2001, section 6.3).

#include <cstddef>
#include <vector>

#include "accel/photon.h"

namespace lenslab {

struct PhotonNeighbour {
    const Photon* photon;
    float dist2;
};

class PhotonKdTree {
public:
    PhotonKdTree() = default;
    // Reorders photons[0, count) into the tree; they must outlive it. Parallel for large sets.
    PhotonKdTree(Photon* photons, size_t count);

    size_t size() const { return m_count; }
    const Photon* begin() const { return m_photons; }
    const Photon* end() const { return m_photons + m_count; }

    // Fills `out` with up to `max_count` photons nearest to `x` within `radius`; if `facing`
    // is given, only photons that arrived from the side it points to (dot(incoming, facing)
    // > 0), so photons on the back of a thin surface neither count nor shrink the radius.
    // Returns the squared radius of the disc the result covers: radius^2 if fewer than
    // `max_count` were found, else the squared distance of the farthest one kept.
    double nearest(const Vec3& x, double radius, size_t max_count, const Vec3* facing,
                   std::vector<PhotonNeighbour>& out) const;

private:
    void build(size_t lo, size_t hi);

    Photon* m_photons = nullptr;
    size_t m_count = 0;
};

}  // namespace lenslab
