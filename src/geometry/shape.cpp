#include "geometry/shape.h"

#include <limits>

namespace lenslab {

bool Shape::contains(const Vec3& p) const {
    if (!is_closed()) return false;
    // An irrational-looking direction, so the probe rarely grazes an edge of a mesh.
    const Vec3 d = normalize(Vec3{0.5773, 0.5921, 0.5624});
    SurfaceHit hit;
    if (!intersect({p, d}, 0.0, std::numeric_limits<double>::infinity(), hit)) return false;
    return dot(hit.normal, d) > 0.0;
}

BoundingSphere Shape::bounding_sphere() const {
    const Aabb b = bounds();
    return {(b.lo + b.hi) * 0.5, 0.5 * length(b.hi - b.lo)};
}

}  // namespace lenslab
