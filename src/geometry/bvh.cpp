#include "geometry/bvh.h"

namespace lenslab {

namespace {
constexpr int kShapesPerLeaf = 4;
}  // namespace

Bvh::Bvh(std::vector<const Shape*> shapes) : m_shapes(std::move(shapes)) {
    std::vector<Aabb> boxes;
    boxes.reserve(m_shapes.size());
    for (const Shape* s : m_shapes) boxes.push_back(s->bounds());
    m_layout = build_bvh(boxes, kShapesPerLeaf);
}

bool Bvh::intersect(const Ray& ray, double t_min, double t_max, BvhHit& hit) const {
    SurfaceHit candidate;
    return traverse_bvh(m_layout.nodes, ray, t_min, t_max, false,
                        [&](int first, int count, double& t_far) {
                            bool found = false;
                            for (int i = first; i < first + count; ++i) {
                                const int p = m_layout.order[i];
                                if (m_shapes[p]->intersect(ray, t_min, t_far, candidate)) {
                                    found = true;
                                    t_far = candidate.t;
                                    hit.surface = candidate;
                                    hit.primitive = p;
                                }
                            }
                            return found;
                        });
}

bool Bvh::occluded(const Ray& ray, double t_min, double t_max,
                   const std::vector<char>* see_through) const {
    SurfaceHit candidate;
    return traverse_bvh(m_layout.nodes, ray, t_min, t_max, true,
                        [&](int first, int count, double& t_far) {
                            for (int i = first; i < first + count; ++i) {
                                const int shape = m_layout.order[i];
                                if (see_through && (*see_through)[static_cast<size_t>(shape)])
                                    continue;
                                if (m_shapes[shape]->intersect(ray, t_min, t_far, candidate)) {
                                    return true;
                                }
                            }
                            return false;
                        });
}

}  // namespace lenslab
