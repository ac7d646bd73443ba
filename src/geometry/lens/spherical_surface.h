#pragma once

#include "geometry/lens/lens_surface.h"

namespace lenslab {

// A spherical cap of signed radius R: its centre of curvature is at (0, 0, R), so R > 0 bends
// towards +z away from the axis (optics sign convention). Only the cap facing the vertex,
// the half of the sphere containing the origin, belongs to the surface.
class SphericalSurface final : public LensSurface {
public:
    explicit SphericalSurface(double radius) : m_radius(radius), m_curvature(1.0 / radius) {}

    double sag(double r) const override;
    double max_semi_diameter() const override;
    bool intersect(const Ray& ray, const SurfaceSpan& span, double t_min, double t_max,
                   double& t) const override;
    bool intersect_reads_bounds() const override { return false; }
    Vec3 normal(const Vec3& p) const override;
    std::string describe() const override;

    VertexSag vertex_sag(double) const override {
        return {m_curvature, m_curvature * m_curvature * m_curvature / 8.0};
    }
    double radius() const { return m_radius; }

private:
    double m_radius;
    double m_curvature;  // 1 / R, divided once: a beam's rays ask for it at every hit
};

}  // namespace lenslab
