#include "geometry/lens/analytic_sag_surface.h"

#include "geometry/lens/sag_intersection.h"

namespace lenslab {

namespace {

struct AnalyticSag {
    const AnalyticSagSurface& s;
    double value(double x, double y) const { return s.sag_xy(x, y); }
    double value_and_gradient(double x, double y, double& dx, double& dy) const {
        return s.sag_and_gradient(x, y, dx, dy);
    }
};

}  // namespace

bool AnalyticSagSurface::intersect(const Ray& ray, const SurfaceSpan& span, double t_min,
                                   double t_max, double& t) const {
    AnalyticSag sag{*this};
    return intersect_sag(ray, span, t_min, t_max, t, sag);
}

Vec3 AnalyticSagSurface::normal(const Vec3& p) const {
    double dx, dy;
    sag_and_gradient(p.x, p.y, dx, dy);
    return normalize(Vec3{-dx, -dy, 1.0});
}

}  // namespace lenslab
