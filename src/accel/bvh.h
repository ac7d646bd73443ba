#pragma once
// Bounding volume hierarchy over the scene's shapes: binned SAH build (Wald 2007,
// "On fast Construction of SAH-based Bounding Volume Hierarchies"), stack traversal
// visiting the nearer child first.

#include <cstdint>
#include <vector>

#include "geometry/shape.h"

namespace lenslab {

struct BvhHit {
    SurfaceHit surface;
    int primitive = -1;
};

class Bvh {
public:
    Bvh() = default;
    // `shapes` must outlive the BVH.
    explicit Bvh(std::vector<const Shape*> shapes);

    bool intersect(const Ray& ray, double t_min, double t_max, BvhHit& hit) const;
    // True if anything lies on the ray within (t_min, t_max): stops at the first hit.
    bool occluded(const Ray& ray, double t_min, double t_max) const;
    Aabb bounds() const { return m_nodes.empty() ? Aabb{} : m_nodes[0].box; }

private:
    struct Node {
        Aabb box;
        int32_t first = 0;   // leaf: first index into m_order; inner: index of the right child
        int32_t count = 0;   // leaf: number of primitives; inner: 0 (left child is this + 1)
        int32_t axis = 0;
    };
    template <bool AnyHit>
    bool traverse(const Ray& ray, double t_min, double t_max, BvhHit* hit) const;
    int build(std::vector<int>& items, int begin, int end, const std::vector<Aabb>& boxes,
              const std::vector<Vec3>& centres, int depth);

    std::vector<const Shape*> m_shapes;
    std::vector<int> m_order;
    std::vector<Node> m_nodes;
};

}  // namespace lenslab
