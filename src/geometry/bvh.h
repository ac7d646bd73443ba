#pragma once
// Bounding volume hierarchy over the scene's shapes (binned SAH build and near-first
// traversal from accel/bvh_build.h).

#include <vector>

#include "accel/bvh_build.h"
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
    // True if anything lies on the ray within (t_min, t_max): stops at the first hit. Shapes
    // marked in `see_through` (by primitive index), when given, do not block it.
    bool occluded(const Ray& ray, double t_min, double t_max,
                  const std::vector<char>* see_through = nullptr) const;
    Aabb bounds() const { return m_layout.nodes.empty() ? Aabb{} : m_layout.nodes[0].box; }

private:
    std::vector<const Shape*> m_shapes;
    BvhLayout m_layout;
};

}  // namespace lenslab
