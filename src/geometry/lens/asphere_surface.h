#pragma once

#include <vector>

#include "geometry/lens/lens_surface.h"

namespace lenslab {

// The even asphere of lens design: a conic of vertex radius R and conic constant k plus an
// even polynomial,
//   z(r) = c r^2 / (1 + sqrt(1 - (1 + k) c^2 r^2)) + A4 r^4 + A6 r^6 + ... + A16 r^16,
// c = 1/R (Smith, Modern Optical Engineering, 4th ed., eq. 18.1; ISO 10110-12). No closed-
// form ray intersection exists, so it is found numerically (sag_intersection.h); sag and
// slope are analytic.
class AsphereSurface final : public LensSurface {
public:
    static constexpr size_t kMaxCoefficients = 7;  // A4 .. A16

    // `coefficients` are A4, A6, ... in order; at most kMaxCoefficients.
    AsphereSurface(double radius, double k, std::vector<double> coefficients);

    double sag(double r) const override;
    double max_semi_diameter() const override;
    bool intersect(const Ray& ray, const SurfaceSpan& span, double t_min, double t_max,
                   double& t) const override;
    Vec3 normal(const Vec3& p) const override;
    std::string describe() const override;
    std::string why_undefined(double x, double y) const override;

    // dz/dr, and the polynomial's share of it.
    double slope(double r) const;
    double polynomial_slope(double r) const;

    VertexSag vertex_sag(double) const override {
        const double c = 1.0 / m_radius;
        const double a4 = m_coefficients.empty() ? 0.0 : m_coefficients[0];
        return {c, (1.0 + m_k) * c * c * c / 8.0 + a4};
    }
    double radius() const { return m_radius; }
    double k() const { return m_k; }
    const std::vector<double>& coefficients() const { return m_coefficients; }

private:
    double m_radius;
    double m_k;
    std::vector<double> m_coefficients;
};

}  // namespace lenslab
