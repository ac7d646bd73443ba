#pragma once
// A toroid (Zemax TOROIDAL): a curve in the y-z plane, a conic of vertex radius R_y with
// even polynomial terms,
//   z_y(y) = c y^2 / (1 + sqrt(1 - (1 + k) c^2 y^2)) + A4 y^4 + A6 y^6 + ...,
// swept about an axis parallel to y at distance R (the radius of rotation) behind the vertex:
//   z = R - sign(R) sqrt((R - z_y(y))^2 - x^2).
// R = 0 sweeps the curve straight along x (a cylinder curved in y); R_y = 0 makes the curve
// straight (with no terms: a cylinder curved in x).

#include <vector>

#include "geometry/lens/analytic_sag_surface.h"

namespace lenslab {

class ToroidalSurface final : public AnalyticSagSurface {
public:
    static constexpr size_t kMaxCoefficients = 7;  // A4 .. A16
    ToroidalSurface(double radius, double k, std::vector<double> coefficients,
                    double radius_of_rotation);

    double sag_and_gradient(double x, double y, double& dz_dx, double& dz_dy) const override;
    double max_semi_diameter() const override;
    std::string describe() const override;
    std::string why_undefined(double x, double y) const override;

private:
    // The y-z curve and its slope.
    double curve(double y, double& slope) const;

    double m_radius, m_c, m_k;
    std::vector<double> m_coefficients;
    double m_rotation;
};

}  // namespace lenslab
