#pragma once
// A surface that is not one of revolution, given by a closed-form sag z(x, y) and its
// gradient (a biconic, a toroid): the crossing found numerically (sag_intersection.h), the
// normal exact from the gradient.

#include <string>

#include "geometry/lens/lens_surface.h"

namespace lenslab {

class AnalyticSagSurface : public LensSurface {
public:
    // The sag at (x, y) and its gradient; NaN where the surface does not exist.
    virtual double sag_and_gradient(double x, double y, double& dz_dx, double& dz_dy) const = 0;

    double sag(double r) const override { return sag_xy(r, 0.0); }
    double sag_xy(double x, double y) const override {
        double dx, dy;
        return sag_and_gradient(x, y, dx, dy);
    }
    bool is_rotationally_symmetric() const override { return false; }
    bool intersect(const Ray& ray, const SurfaceSpan& span, double t_min, double t_max,
                   double& t) const override;
    Vec3 normal(const Vec3& p) const override;
};

}  // namespace lenslab
