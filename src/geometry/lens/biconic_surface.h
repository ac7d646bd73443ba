#pragma once
// A biconic: a conic section in x and another in y, with their own vertex radii and conic
// constants (Zemax BICONICX without its polynomial; cylinders and anamorphic lenses):
//   z = (cx x^2 + cy y^2) / (1 + sqrt(1 - (1 + kx) cx^2 x^2 - (1 + ky) cy^2 y^2)).
// A radius of 0 leaves that section straight (cx = 0): a cylinder.

#include "geometry/lens/analytic_sag_surface.h"

namespace lenslab {

class BiconicSurface final : public AnalyticSagSurface {
public:
    BiconicSurface(double radius_x, double radius_y, double k_x, double k_y);

    double sag_and_gradient(double x, double y, double& dz_dx, double& dz_dy) const override;
    double max_semi_diameter() const override;
    std::string describe() const override;
    std::string why_undefined(double x, double y) const override;

private:
    double m_radius_x, m_radius_y, m_cx, m_cy, m_kx, m_ky;
};

}  // namespace lenslab
