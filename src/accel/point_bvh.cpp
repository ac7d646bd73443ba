#include "accel/point_bvh.h"

#include <algorithm>
#include <numeric>

namespace lenslab {

namespace {
constexpr uint32_t kLeafPoints = 8;
}

PointBvh::PointBvh(size_t count, const std::function<Vec3(size_t)>& position,
                   const std::function<double(size_t)>& radius) {
    m_order.resize(count);
    std::iota(m_order.begin(), m_order.end(), uint32_t{0});
    m_points.resize(count);
    m_radius2.resize(count);
    for (size_t i = 0; i < count; ++i) {
        m_points[i] = position(i);
        m_radius2[i] = radius(i);  // the radius until the tree is built
    }
    if (count == 0) return;
    m_nodes.reserve(2 * count / kLeafPoints + 2);
    build(0, static_cast<uint32_t>(count));
    // Points in leaf order, so a leaf's are contiguous.
    std::vector<Vec3> points(count);
    std::vector<double> radius2(count);
    for (size_t k = 0; k < count; ++k) {
        points[k] = m_points[m_order[k]];
        radius2[k] = m_radius2[m_order[k]] * m_radius2[m_order[k]];
    }
    m_points.swap(points);
    m_radius2.swap(radius2);
}

// Splits [first, last) of m_order at the median of the box's longest axis; the points and
// radii are still in the caller's order here.
uint32_t PointBvh::build(uint32_t first, uint32_t last) {
    const uint32_t index = static_cast<uint32_t>(m_nodes.size());
    m_nodes.emplace_back();
    Aabb box, grown;
    for (uint32_t k = first; k < last; ++k) {
        const Vec3& p = m_points[m_order[k]];
        const double r = m_radius2[m_order[k]];
        box.expand(p);
        grown.expand(Aabb{p - Vec3{r, r, r}, p + Vec3{r, r, r}});
    }
    m_nodes[index].box = grown;
    if (last - first <= kLeafPoints) {
        m_nodes[index].first = first;
        m_nodes[index].count = last - first;
        return index;
    }
    const Vec3 e = box.extent();
    const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
    const uint32_t mid = first + (last - first) / 2;
    std::nth_element(m_order.begin() + first, m_order.begin() + mid, m_order.begin() + last,
                     [&](uint32_t a, uint32_t b) { return m_points[a][axis] < m_points[b][axis]; });
    build(first, mid);
    const uint32_t right = build(mid, last);
    m_nodes[index].first = right;
    return index;
}

}  // namespace lenslab
