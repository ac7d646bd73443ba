#pragma once
// A bounding volume hierarchy over points, each with a radius of its own, answering one
// question fast: which points lie within their radius of a ray segment. The beam radiance
// estimate (Jarosz, Zwicker and Jensen 2008) asks it of every camera ray through fog: the
// volume photons whose discs the ray crosses.

#include <cstdint>
#include <functional>
#include <vector>

#include "math/aabb.h"

namespace lenslab {

class PointBvh {
public:
    // `position(i)` and `radius(i)` for i in [0, count).
    PointBvh(size_t count, const std::function<Vec3(size_t)>& position,
             const std::function<double(size_t)>& radius);

    // Calls `visit(i, t, r2)` for each point i within its radius of the segment
    // ray.at([0, t_max]): t its projection on the ray (in [0, t_max]), r2 its squared radius.
    // `ray.direction` is unit.
    template <class Visit>
    void for_each_near(const Ray& ray, double t_max, const Visit& visit) const;

private:
    struct Node {
        Aabb box;            // of its points, grown by the radius
        uint32_t first = 0;  // leaf: its points m_order[first, first + count); inner: right child
        uint32_t count = 0;  // 0: inner node, its left child next in m_nodes
    };
    uint32_t build(uint32_t first, uint32_t last);

    std::vector<Vec3> m_points;     // in leaf order once built
    std::vector<double> m_radius2;  // the same, each point's squared radius
    std::vector<uint32_t> m_order;  // the caller's index of each
    std::vector<Node> m_nodes;
};

template <class Visit>
void PointBvh::for_each_near(const Ray& ray, double t_max, const Visit& visit) const {
    if (m_nodes.empty()) return;
    const Vec3 inv{1.0 / ray.direction.x, 1.0 / ray.direction.y, 1.0 / ray.direction.z};
    uint32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& n = m_nodes[stack[--top]];
        if (!n.box.hit(ray, inv, 0.0, t_max)) continue;
        if (n.count == 0) {
            const uint32_t self = static_cast<uint32_t>(&n - m_nodes.data());
            stack[top++] = n.first;
            stack[top++] = self + 1;
            continue;
        }
        for (uint32_t k = n.first; k < n.first + n.count; ++k) {
            const Vec3 v = m_points[k] - ray.origin;
            const double t = dot(v, ray.direction);
            if (t < 0.0 || t > t_max) continue;
            if (length_squared(v) - t * t <= m_radius2[k])
                visit(size_t{m_order[k]}, t, m_radius2[k]);
        }
    }
}

}  // namespace lenslab
