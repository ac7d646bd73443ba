#include "accel/photon_kdtree.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <limits>

namespace lenslab {

namespace {

// Below this many photons a subtree is built on the current thread.
constexpr size_t kParallelBuildThreshold = 1 << 15;
// Ranges this small are scanned linearly by queries instead of descended.
constexpr size_t kLeafSize = 16;

}  // namespace

PhotonKdTree::PhotonKdTree(Photon* photons, size_t count) : m_photons(photons), m_count(count) {
    build(0, count);
}

void PhotonKdTree::build(size_t lo, size_t hi) {
    if (hi - lo < 2) {
        if (hi > lo) m_photons[lo].split_axis = 0;
        return;
    }
    float box_lo[3] = {std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
                       std::numeric_limits<float>::max()};
    float box_hi[3] = {-box_lo[0], -box_lo[1], -box_lo[2]};
    for (size_t i = lo; i < hi; ++i) {
        for (int a = 0; a < 3; ++a) {
            box_lo[a] = std::min(box_lo[a], m_photons[i].position[a]);
            box_hi[a] = std::max(box_hi[a], m_photons[i].position[a]);
        }
    }
    int axis = 0;
    for (int a = 1; a < 3; ++a) {
        if (box_hi[a] - box_lo[a] > box_hi[axis] - box_lo[axis]) axis = a;
    }
    const size_t mid = lo + (hi - lo) / 2;
    std::nth_element(
        m_photons + lo, m_photons + mid, m_photons + hi,
        [axis](const Photon& a, const Photon& b) { return a.position[axis] < b.position[axis]; });
    m_photons[mid].split_axis = static_cast<uint8_t>(axis);
    if (hi - lo > kParallelBuildThreshold) {
        tbb::parallel_invoke([&] { build(lo, mid); }, [&] { build(mid + 1, hi); });
    } else {
        build(lo, mid);
        build(mid + 1, hi);
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

    // Explicit stack of ranges; each carries the squared distance from x to its half-space,
    // so a far half pushed early is skipped once the search radius has shrunk below it.
    struct Range {
        size_t lo, hi;
        double plane_dist2;
    };
    Range stack[128];
    int top = 0;
    stack[top++] = {0, m_count, 0.0};
    auto consider = [&](const Photon& ph) {
        const double dx = p[0] - ph.position[0], dy = p[1] - ph.position[1],
                     dz = p[2] - ph.position[2];
        const double dist2 = dx * dx + dy * dy + dz * dz;
        if (dist2 >= r2) return;
        if (facing && dot(ph.incoming(), *facing) <= 0.0) return;
        if (out.size() < max_count) {
            // Plain appends until the cap is reached; only then does the order matter.
            out.push_back({&ph, static_cast<float>(dist2)});
            if (out.size() == max_count) {
                std::make_heap(out.begin(), out.end(), farther);
                r2 = out.front().dist2;
            }
        } else {
            std::pop_heap(out.begin(), out.end(), farther);
            out.back() = {&ph, static_cast<float>(dist2)};
            std::push_heap(out.begin(), out.end(), farther);
            r2 = out.front().dist2;
        }
    };
    while (top > 0) {
        const Range range = stack[--top];
        if (range.plane_dist2 >= r2) continue;
        if (range.hi - range.lo <= kLeafSize) {
            // Small subtrees are cheaper to scan than to descend.
            for (size_t i = range.lo; i < range.hi; ++i) consider(m_photons[i]);
            continue;
        }
        const size_t mid = range.lo + (range.hi - range.lo) / 2;
        const Photon& ph = m_photons[mid];
        const int axis = ph.split_axis;
        const double d = static_cast<double>(p[axis]) - ph.position[axis];
        // Push the far half first so the near half is searched first.
        if (d < 0) {
            stack[top++] = {mid + 1, range.hi, d * d};
            stack[top++] = {range.lo, mid, 0.0};
        } else {
            stack[top++] = {range.lo, mid, d * d};
            stack[top++] = {mid + 1, range.hi, 0.0};
        }
        consider(ph);
    }
    return r2;
}

}  // namespace lenslab
