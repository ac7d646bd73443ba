#pragma once

#include "geometry/lens/lens_surface.h"

namespace lenslab {

// The plane z = 0.
class FlatSurface final : public LensSurface {
public:
    double sag(double) const override { return 0.0; }
    double max_semi_diameter() const override;
    bool intersect(const Ray& ray, const SurfaceSpan& span, double t_min, double t_max,
                   double& t) const override;
    bool intersect_reads_bounds() const override { return false; }
    Vec3 normal(const Vec3&) const override { return {0, 0, 1}; }
    VertexSag vertex_sag(double) const override { return {}; }
    std::string describe() const override { return "flat"; }
};

}  // namespace lenslab
