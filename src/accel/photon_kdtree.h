#pragma once
// Balanced kd-tree over photons (Jensen 2001, section 6.3): each range [lo, hi) is split at
// its median along the axis of its largest extent (the report cycled X, Y, Z; the widest axis
// gives tighter cells), down to leaves of at most 32 photons. The photons themselves are
// reordered into the leaves; the split planes live apart, 8 bytes each in breadth-first
// order, so a query walks down a small array that stays in cache and touches photons only in
// the leaves it scans (reading the median photon at every level was the query's main cost:
// each one a cache miss). Queries are k-nearest within a radius. The leaves' positions are
// also kept apart, x, y and z in arrays of their own, so a leaf's distances are one loop the
// compiler vectorises; distances are squared and summed in float, as positions are stored.

#include <cstddef>
#include <cstdint>
#include <memory>
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

    // The split planes' memory (the photons belong to their owner).
    size_t memory_bytes() const {
        return m_splits.capacity() * sizeof(Split) + 3 * m_count * sizeof(float);
    }

private:
    struct Split {
        float value;    // photons of the lower child have position[axis] <= value, the upper >=
        uint32_t axis;  // 0, 1, 2
    };

    void build(size_t node, size_t lo, size_t hi);

    Photon* m_photons = nullptr;
    size_t m_count = 0;
    std::vector<Split> m_splits;     // node i's children are 2i + 1 and 2i + 2
    std::unique_ptr<float[]> m_xyz;  // the photons' x, then their y, then z, in tree order
};

}  // namespace lenslab
