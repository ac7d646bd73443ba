#include "accel/photon_kdtree.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <limits>

#include "util/huge_pages.h"

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
    // Not zero-filled first: the parallel fill is the arrays' first touch, so their page
    // faults are spread over the threads.
    m_xyz = std::make_unique_for_overwrite<float[]>(3 * count);
    advise_huge_pages(m_xyz.get(), 3 * count * sizeof(float));
    tbb::parallel_for(size_t{0}, count, [&](size_t i) {
        for (size_t a = 0; a < 3; ++a) m_xyz[a * count + i] = photons[i].position[a];
    });
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
    if (m_count == 0 || max_count == 0) return radius * radius;
    // Distances in float, as the positions are: a cell's bound is summed as a photon's
    // distance is, so it never exceeds the distance of a photon in the cell.
    float r2 = static_cast<float>(radius * radius);
    const float p[3] = {static_cast<float>(x.x), static_cast<float>(x.y), static_cast<float>(x.z)};
    auto farther = [](const PhotonNeighbour& a, const PhotonNeighbour& b) {
        return a.dist2 < b.dist2;
    };

    // Walks down to the near child directly and keeps only the far ones on a stack. Each
    // subtree carries its offsets from x along the three axes (zero where x lies within its
    // slab), so its squared distance bounds every photon's in it, not just the last plane's
    // (Arya and Mount 1993): far cells across two planes are skipped once the radius shrinks.
    // The bound sums the squares in the photons' own order, so it never exceeds a photon's
    // distance as computed below and the result is the same photons as a plain descent's.
    struct Subtree {
        size_t node, lo, hi;
        float offset[3];
        float dist2;
    };
    Subtree stack[128];
    int top = 0;
    Subtree t{0, 0, m_count, {0.0f, 0.0f, 0.0f}, 0.0f};
    float dist2[kLeafSize];
    for (;;) {
        if (t.hi - t.lo > kLeafSize) {
            const Split& split = m_splits[t.node];
            // The grandchildren's planes (four in a row): loading them while this plane is
            // compared hides the next step's cache miss.
            const size_t grandchildren = 4 * t.node + 3;
            if (grandchildren < m_splits.size()) __builtin_prefetch(&m_splits[grandchildren]);
            const size_t mid = t.lo + (t.hi - t.lo) / 2;
            const float d = p[split.axis] - split.value;
            Subtree far = d < 0 ? Subtree{2 * t.node + 2, mid, t.hi, {}, 0.0f}
                                : Subtree{2 * t.node + 1, t.lo, mid, {}, 0.0f};
            // Selects rather than an indexed store: the offsets stay in registers.
            for (uint32_t a = 0; a < 3; ++a) far.offset[a] = a == split.axis ? d : t.offset[a];
            far.dist2 = far.offset[0] * far.offset[0] + far.offset[1] * far.offset[1] +
                        far.offset[2] * far.offset[2];
            if (far.dist2 < r2) stack[top++] = far;
            if (d < 0) {
                t.node = 2 * t.node + 1;
                t.hi = mid;
            } else {
                t.node = 2 * t.node + 2;
                t.lo = mid;
            }
            continue;
        }
        // The leaf's distances first, from its positions' own arrays (a loop the compiler
        // vectorises), then the few within the radius.
        const size_t n = t.hi - t.lo;
        const float* xs = m_xyz.get() + t.lo;
        const float* ys = xs + m_count;
        const float* zs = ys + m_count;
        for (size_t j = 0; j < n; ++j) {
            const float dx = p[0] - xs[j], dy = p[1] - ys[j], dz = p[2] - zs[j];
            dist2[j] = dx * dx + dy * dy + dz * dz;
        }
        for (size_t j = 0; j < n; ++j) {
            if (dist2[j] >= r2) continue;
            const Photon& ph = m_photons[t.lo + j];
            if (facing && !ph.arrived_from_side(*facing)) continue;
            if (out.size() < max_count) {
                // Plain appends until the cap is reached; only then does the order matter.
                out.push_back({&ph, dist2[j]});
                if (out.size() < max_count) continue;
                std::make_heap(out.begin(), out.end(), farther);
            } else {
                std::pop_heap(out.begin(), out.end(), farther);
                out.back() = {&ph, dist2[j]};
                std::push_heap(out.begin(), out.end(), farther);
            }
            r2 = out.front().dist2;
        }
        // The next far half still within the (perhaps shrunk) radius.
        do {
            if (top == 0) return out.size() < max_count ? radius * radius : r2;
            t = stack[--top];
        } while (t.dist2 >= r2);
    }
}

}  // namespace lenslab
