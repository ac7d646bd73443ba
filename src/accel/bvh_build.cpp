#include "accel/bvh_build.h"

#include <algorithm>
#include <array>
#include <atomic>

#include "accel/bvh_stats.h"

namespace lenslab {

namespace {

// Relaxed: a count read after the builds, never used to order anything.
std::atomic<uint64_t> g_builds{0};

constexpr int kBins = 16;
// Past this depth nodes split at the median, which bounds the remaining depth by log2(n):
// SAH alone can make a chain as deep as the primitive count (objects at scales 2^k).
constexpr int kMaxSahDepth = 48;
static_assert(kMaxSahDepth + 32 + 1 < kBvhStackSize, "the traversal stack must hold any path");

double surface_area(const Aabb& b) {
    if (b.empty()) return 0.0;
    const Vec3 e = b.extent();
    return 2.0 * (e.x * e.y + e.y * e.z + e.z * e.x);
}

class Builder {
public:
    Builder(const std::vector<Aabb>& boxes, int max_leaf_size, BvhLayout& out)
        : m_boxes(boxes), m_max_leaf_size(max_leaf_size), m_out(out) {
        m_centres.reserve(boxes.size());
        for (const Aabb& b : boxes) m_centres.push_back(b.centre());
    }

    int build(int begin, int end, int depth) {
        std::vector<int>& items = m_out.order;
        const int index = static_cast<int>(m_out.nodes.size());
        m_out.nodes.push_back({});
        Aabb box, centre_box;
        for (int i = begin; i < end; ++i) {
            box.expand(m_boxes[items[i]]);
            centre_box.expand(m_centres[items[i]]);
        }
        m_out.nodes[index].box = box;
        const int count = end - begin;
        const Vec3 extent = centre_box.extent();
        const int axis =
            extent.x > extent.y ? (extent.x > extent.z ? 0 : 2) : (extent.y > extent.z ? 1 : 2);
        if (count <= m_max_leaf_size) {
            m_out.nodes[index].first = begin;
            m_out.nodes[index].count = count;
            return index;
        }
        m_out.nodes[index].axis = axis;
        // Coincident centres (a pile of copies of one triangle) leave no plane to split at:
        // halve the range by index, or one leaf would hold them all and every ray reaching
        // it would test each. The negation also catches NaN centres.
        const bool coincident = !(extent[axis] > 0.0);
        const int mid = coincident              ? begin + count / 2
                        : depth >= kMaxSahDepth ? median_split(begin, end, axis)
                                                : sah_split(begin, end, axis, centre_box);
        build(begin, mid, depth + 1);
        const int right = build(mid, end, depth + 1);
        m_out.nodes[index].first = right;
        m_out.nodes[index].count = 0;
        return index;
    }

private:
    int median_split(int begin, int end, int axis) {
        std::vector<int>& items = m_out.order;
        const int mid = begin + (end - begin) / 2;
        std::nth_element(items.begin() + begin, items.begin() + mid, items.begin() + end,
                         [&](int a, int b) { return m_centres[a][axis] < m_centres[b][axis]; });
        return mid;
    }

    // Binned SAH along the widest centroid axis.
    int sah_split(int begin, int end, int axis, const Aabb& centre_box) {
        std::vector<int>& items = m_out.order;
        struct Bin {
            Aabb box;
            int count = 0;
        };
        std::array<Bin, kBins> bins;
        const double lo = centre_box.lo[axis];
        const double scale = kBins / centre_box.extent()[axis];
        auto bin_of = [&](int item) {
            return std::min(kBins - 1, static_cast<int>((m_centres[item][axis] - lo) * scale));
        };
        for (int i = begin; i < end; ++i) {
            Bin& b = bins[bin_of(items[i])];
            b.box.expand(m_boxes[items[i]]);
            ++b.count;
        }
        std::array<double, kBins - 1> cost{};
        Aabb left;
        int left_count = 0;
        for (int s = 0; s < kBins - 1; ++s) {
            left.expand(bins[s].box);
            left_count += bins[s].count;
            cost[s] = left_count * surface_area(left);
        }
        Aabb right;
        int right_count = 0;
        for (int s = kBins - 1; s > 0; --s) {
            right.expand(bins[s].box);
            right_count += bins[s].count;
            cost[s - 1] += right_count * surface_area(right);
        }
        const int split =
            static_cast<int>(std::min_element(cost.begin(), cost.end()) - cost.begin());
        const int mid =
            static_cast<int>(std::partition(items.begin() + begin, items.begin() + end,
                                            [&](int item) { return bin_of(item) <= split; }) -
                             items.begin());
        if (mid == begin || mid == end) return begin + (end - begin) / 2;  // all in one bin
        return mid;
    }

    const std::vector<Aabb>& m_boxes;
    std::vector<Vec3> m_centres;
    int m_max_leaf_size;
    BvhLayout& m_out;
};

}  // namespace

BvhLayout build_bvh(const std::vector<Aabb>& boxes, int max_leaf_size) {
    g_builds.fetch_add(1, std::memory_order_relaxed);
    BvhLayout layout;
    const int n = static_cast<int>(boxes.size());
    if (n == 0) return layout;
    layout.order.resize(n);
    for (int i = 0; i < n; ++i) layout.order[i] = i;
    layout.nodes.reserve(2 * static_cast<size_t>(n));
    Builder(boxes, std::max(1, max_leaf_size), layout).build(0, n, 0);
    return layout;
}

uint64_t bvh_build_count() { return g_builds.load(std::memory_order_relaxed); }

BvhStats bvh_stats(const BvhLayout& layout) {
    BvhStats stats;
    stats.nodes = layout.nodes.size();
    for (const BvhNode& n : layout.nodes) {
        if (n.count == 0) continue;
        ++stats.leaves;
        stats.max_leaf_size = std::max(stats.max_leaf_size, static_cast<int>(n.count));
    }
    return stats;
}

}  // namespace lenslab
