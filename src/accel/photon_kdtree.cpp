#include "accel/photon_kdtree.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <limits>

namespace lenslab {

namespace {

// Below this many photons a subtree is built on the current thread.
constexpr size_t kParallelBuildThreshold = 1 << 15;
// Ranges this small are scanned linearly by queries instead of descended.
constexpr size_t kLeafSize = 32;
// Photons looked at to choose a range's split axis.
constexpr size_t kExtentSamples = 256;

// The number of split nodes a tree over `count` photons needs in breadth-first order: the
// upper half of a range (it holds the median) is the larger, so the deepest leaf is on the
// path that always takes it.
size_t split_nodes_for(size_t count) {
    int depth = 0;
    for (size_t s = count; s > kLeafSize; s -= s / 2) ++depth;
    return (size_t{1} << depth) - 1;
}

}  // namespace

PhotonKdTree::PhotonKdTree(Photon* photons, size_t count)
    : m_photons(photons), m_count(count), m_splits(split_nodes_for(count)) {
    build(0, 0, count);
}

void PhotonKdTree::build(size_t node, size_t lo, size_t hi) {
    if (hi - lo <= kLeafSize) return;
    // The range's extent, from at most about kExtentSamples photons spread over it: the
    // widest axis needs only a rough extent, and a full scan at every level cost as much as
    // the median selection itself.
    const size_t step = std::max<size_t>(1, (hi - lo) / kExtentSamples);
    float box_lo[3] = {std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
                       std::numeric_limits<float>::max()};
    float box_hi[3] = {-box_lo[0], -box_lo[1], -box_lo[2]};
    for (size_t i = lo; i < hi; i += step) {
        for (int a = 0; a < 3; ++a) {
            box_lo[a] = std::min(box_lo[a], m_photons[i].position[a]);
            box_hi[a] = std::max(box_hi[a], m_photons[i].position[a]);
        }
    }
    uint32_t axis = 0;
    for (uint32_t a = 1; a < 3; ++a) {
        if (box_hi[a] - box_lo[a] > box_hi[axis] - box_lo[axis]) axis = a;
    }
    const size_t mid = lo + (hi - lo) / 2;
    std::nth_element(
        m_photons + lo, m_photons + mid, m_photons + hi,
        [axis](const Photon& a, const Photon& b) { return a.position[axis] < b.position[axis]; });
    m_splits[node] = {m_photons[mid].position[axis], axis};
    if (hi - lo > kParallelBuildThreshold) {
        tbb::parallel_invoke([&] { build(2 * node + 1, lo, mid); },
                             [&] { build(2 * node + 2, mid, hi); });
    } else {
        build(2 * node + 1, lo, mid);
        build(2 * node + 2, mid, hi);
    }
}

double PhotonKdTree::nearest(const Vec3& x, double radius, size_t max_count, const Vec3* facing,
                             std::vector<PhotonNeighbour>& out) const {
    out.clear();
    double r2 = radius * radius;
    if (m_count == 0 || max_count == 0) return r2;
    const float p[3] = {static_cast<float>(x.x), static_cast<float>(x.y), static_cast<float>(x.z)};
    auto farther = [](const PhotonNeighbour& a, const PhotonNeighbour& b) {
        return a.dist2 < b.dist2;
    };

    // Walks down to the near child directly and keeps only the far ones on a stack; each
    // carries the squared distance from x to its half-space, so a far half is skipped once
    // the search radius has shrunk below it.
    struct Subtree {
        size_t node, lo, hi;
        double plane_dist2;
    };
    Subtree stack[128];
    int top = 0;
    Subtree t{0, 0, m_count, 0.0};
    for (;;) {
        if (t.hi - t.lo > kLeafSize) {
            const Split& split = m_splits[t.node];
            // The grandchildren's planes (four in a row): loading them while this plane is
            // compared hides the next step's cache miss.
            const size_t grandchildren = 4 * t.node + 3;
            if (grandchildren < m_splits.size()) __builtin_prefetch(&m_splits[grandchildren]);
            const size_t mid = t.lo + (t.hi - t.lo) / 2;
            const double d = static_cast<double>(p[split.axis]) - split.value;
            const Subtree lower{2 * t.node + 1, t.lo, mid, d * d};
            const Subtree upper{2 * t.node + 2, mid, t.hi, d * d};
            if (d * d < r2) stack[top++] = d < 0 ? upper : lower;
            t = d < 0 ? lower : upper;
            continue;
        }
        for (size_t i = t.lo; i < t.hi; ++i) {
            const Photon& ph = m_photons[i];
            const double dx = p[0] - ph.position[0], dy = p[1] - ph.position[1],
                         dz = p[2] - ph.position[2];
            const double dist2 = dx * dx + dy * dy + dz * dz;
            if (dist2 >= r2) continue;
            if (facing && !ph.arrived_from_side(*facing)) continue;
            if (out.size() < max_count) {
                // Plain appends until the cap is reached; only then does the order matter.
                out.push_back({&ph, static_cast<float>(dist2)});
                if (out.size() < max_count) continue;
                std::make_heap(out.begin(), out.end(), farther);
            } else {
                std::pop_heap(out.begin(), out.end(), farther);
                out.back() = {&ph, static_cast<float>(dist2)};
                std::push_heap(out.begin(), out.end(), farther);
            }
            r2 = out.front().dist2;
        }
        // The next far half still within the (perhaps shrunk) radius.
        do {
            if (top == 0) return r2;
            t = stack[--top];
        } while (t.plane_dist2 >= r2);
    }
}

}  // namespace lenslab
