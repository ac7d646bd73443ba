#pragma once

#include "geometry/lens/lens_surface.h"

namespace lenslab {

// A conic of revolution with vertex radius R (curvature c = 1/R, optics sign convention) and
// conic constant k: z(r) = c r^2 / (1 + sqrt(1 - (1 + k) c^2 r^2)). k = 0 is a sphere,
// -1 < k < 0 a prolate ellipsoid, k > 0 an oblate one, k = -1 a paraboloid, k < -1 a
// hyperboloid (Smith, Modern Optical Engineering, 4th ed., section 18.3). It is the quadric
// c (x^2 + y^2 + (1 + k) z^2) - 2 z = 0, so a ray meets it in closed form; only the sheet
// through the vertex, where (1 + k) c z <= 1, belongs to the surface.
class ConicSurface final : public LensSurface {
public:
    ConicSurface(double radius, double k) : m_radius(radius), m_k(k), m_curvature(1.0 / radius) {}

    double sag(double r) const override;
    double max_semi_diameter() const override;
    bool intersect(const Ray& ray, const SurfaceSpan& span, double t_min, double t_max,
                   double& t) const override;
    bool intersect_reads_bounds() const override { return false; }
    Vec3 normal(const Vec3& p) const override;
    std::string describe() const override;
    std::string why_undefined(double x, double y) const override;

    VertexSag vertex_sag(double) const override {
        return {m_curvature, (1.0 + m_k) * m_curvature * m_curvature * m_curvature / 8.0};
    }
    double radius() const { return m_radius; }
    double k() const { return m_k; }

    // The conic's sag and slope dz/dr, shared with the asphere built on it.
    static double conic_sag(double c, double k, double r);
    static double conic_slope(double c, double k, double r);
    // Largest r where the conic exists: 1 / (|c| sqrt(1 + k)) for k > -1, else unbounded.
    static double conic_max_semi_diameter(double c, double k);

private:
    double m_radius;
    double m_k;
    double m_curvature;  // 1 / R, divided once: a beam's rays ask for it at every hit
};

}  // namespace lenslab
