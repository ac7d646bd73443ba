#include "geometry/lens/flat_surface.h"

#include <limits>

namespace lenslab {

double FlatSurface::max_semi_diameter() const { return std::numeric_limits<double>::infinity(); }

bool FlatSurface::intersect(const Ray& ray, const SurfaceSpan& span, double t_min, double t_max,
                            double& t) const {
    if (ray.direction.z == 0.0) return false;
    const double tc = -ray.origin.z / ray.direction.z;
    if (!in_range(tc, t_min, t_max)) return false;
    const Vec3 p = ray.at(tc);
    const double limit = span.semi_diameter * (1.0 + kSeamTolerance);
    if (p.x * p.x + p.y * p.y > limit * limit) return false;
    t = tc;
    return true;
}

}  // namespace lenslab
