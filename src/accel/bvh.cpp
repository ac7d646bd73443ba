#include "accel/bvh.h"

#include <algorithm>
#include <array>

namespace lenslab {

namespace {

constexpr int kBins = 16;
constexpr int kMaxLeafSize = 4;
// Past this depth nodes split at the median, which bounds the remaining depth by log2(n):
// SAH alone can make a chain as deep as the primitive count (objects at scales 2^k).
constexpr int kMaxSahDepth = 48;
constexpr int kStackSize = 128;

double surface_area(const Aabb& b) {
    if (b.empty()) return 0.0;
    const Vec3 e = b.extent();
    return 2.0 * (e.x * e.y + e.y * e.z + e.z * e.x);
}

}  // namespace

Bvh::Bvh(std::vector<const Shape*> shapes) : m_shapes(std::move(shapes)) {
    const int n = static_cast<int>(m_shapes.size());
    if (n == 0) return;
    std::vector<Aabb> boxes(n);
    std::vector<Vec3> centres(n);
    for (int i = 0; i < n; ++i) {
        boxes[i] = m_shapes[i]->bounds();
        centres[i] = boxes[i].centre();
    }
    m_order.resize(n);
    for (int i = 0; i < n; ++i) m_order[i] = i;
    m_nodes.reserve(2 * n);
    build(m_order, 0, n, boxes, centres, 0);
}

int Bvh::build(std::vector<int>& items, int begin, int end, const std::vector<Aabb>& boxes,
               const std::vector<Vec3>& centres, int depth) {
    const int index = static_cast<int>(m_nodes.size());
    m_nodes.push_back({});
    Aabb box, centre_box;
    for (int i = begin; i < end; ++i) {
        box.expand(boxes[items[i]]);
        centre_box.expand(centres[items[i]]);
    }
    m_nodes[index].box = box;
    const int count = end - begin;
    const Vec3 extent = centre_box.extent();
    int axis = extent.x > extent.y ? (extent.x > extent.z ? 0 : 2) : (extent.y > extent.z ? 1 : 2);
    if (count <= kMaxLeafSize || extent[axis] <= 0.0) {
        m_nodes[index].first = begin;
        m_nodes[index].count = count;
        return index;
    }

    m_nodes[index].axis = axis;
    if (depth >= kMaxSahDepth) {
        const int mid = begin + count / 2;
        std::nth_element(items.begin() + begin, items.begin() + mid, items.begin() + end,
                         [&](int a, int b) { return centres[a][axis] < centres[b][axis]; });
        build(items, begin, mid, boxes, centres, depth + 1);
        m_nodes[index].first = build(items, mid, end, boxes, centres, depth + 1);
        m_nodes[index].count = 0;
        return index;
    }

    // Binned SAH along the widest centroid axis.
    struct Bin { Aabb box; int count = 0; };
    std::array<Bin, kBins> bins;
    const double scale = kBins / extent[axis];
    auto bin_of = [&](int item) {
        return std::min(kBins - 1, static_cast<int>((centres[item][axis] - centre_box.lo[axis]) * scale));
    };
    for (int i = begin; i < end; ++i) {
        Bin& b = bins[bin_of(items[i])];
        b.box.expand(boxes[items[i]]);
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
    const int split = static_cast<int>(std::min_element(cost.begin(), cost.end()) - cost.begin());
    int mid = static_cast<int>(
        std::partition(items.begin() + begin, items.begin() + end,
                       [&](int item) { return bin_of(item) <= split; }) - items.begin());
    if (mid == begin || mid == end) mid = begin + count / 2;  // all in one bin: split in half

    build(items, begin, mid, boxes, centres, depth + 1);
    m_nodes[index].first = build(items, mid, end, boxes, centres, depth + 1);
    m_nodes[index].count = 0;
    return index;
}

template <bool AnyHit>
bool Bvh::traverse(const Ray& ray, double t_min, double t_max, BvhHit* hit) const {
    if (m_nodes.empty()) return false;
    const Vec3 inv{1.0 / ray.direction.x, 1.0 / ray.direction.y, 1.0 / ray.direction.z};
    int stack[kStackSize];  // depth <= kMaxSahDepth + log2(n) + 1, far below the size
    int top = 0;
    stack[top++] = 0;
    bool found = false;
    SurfaceHit candidate;
    while (top > 0) {
        const Node& node = m_nodes[stack[--top]];
        if (!node.box.hit(ray, inv, t_min, t_max)) continue;
        if (node.count > 0) {
            for (int i = node.first; i < node.first + node.count; ++i) {
                if (m_shapes[m_order[i]]->intersect(ray, t_min, t_max, candidate)) {
                    if constexpr (AnyHit) return true;
                    found = true;
                    t_max = candidate.t;
                    hit->surface = candidate;
                    hit->primitive = m_order[i];
                }
            }
            continue;
        }
        const int near = static_cast<int>(&node - m_nodes.data()) + 1;
        const int far = node.first;
        // Push the far child first so the near one is visited first and shrinks t_max.
        if (ray.direction[node.axis] < 0) {
            stack[top++] = near;
            stack[top++] = far;
        } else {
            stack[top++] = far;
            stack[top++] = near;
        }
    }
    return found;
}

bool Bvh::intersect(const Ray& ray, double t_min, double t_max, BvhHit& hit) const {
    return traverse<false>(ray, t_min, t_max, &hit);
}

bool Bvh::occluded(const Ray& ray, double t_min, double t_max) const {
    return traverse<true>(ray, t_min, t_max, nullptr);
}

}  // namespace lenslab
