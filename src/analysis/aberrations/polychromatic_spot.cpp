#include "analysis/aberrations/polychromatic_spot.h"

#include <algorithm>
#include <cmath>

#include "analysis/system/real_ray.h"

namespace lenslab {

PolychromaticSpot polychromatic_spot(const std::vector<FieldBeam>& beams,
                                     const std::vector<double>& weights, double image_z) {
    PolychromaticSpot spot;
    // Weighted sums of the hits and of their squares: the mean square radius about the
    // centroid is E[x² + y²] - |E[(x, y)]|².
    double w_sum = 0, sx = 0, sy = 0, sxx = 0;
    for (size_t i = 0; i < beams.size(); ++i) {
        const double w = weights.empty() ? 1.0 : weights[i];
        const FieldBeam& beam = beams[i];
        spot.rays += static_cast<int>(beam.rays.size()) + beam.lost;
        spot.lost += beam.lost;
        for (const ExitRay& r : beam.rays) {
            const Vec3 p = at_plane(r.point, r.direction, image_z);
            w_sum += w;
            sx += w * p.x;
            sy += w * p.y;
            sxx += w * (p.x * p.x + p.y * p.y);
        }
    }
    if (!(w_sum > 0)) {
        spot.rms_radius = NAN;
        return spot;
    }
    spot.centroid_x = sx / w_sum;
    spot.centroid_y = sy / w_sum;
    const double mean_square =
        sxx / w_sum - spot.centroid_x * spot.centroid_x - spot.centroid_y * spot.centroid_y;
    spot.rms_radius = std::sqrt(std::max(mean_square, 0.0));
    return spot;
}

PolychromaticSpot polychromatic_rms_spot(const OpticalSystem& system, const FirstOrder& first_order,
                                         double field, const std::vector<double>& wavelengths,
                                         const std::vector<double>& weights, int rings,
                                         double image_z) {
    std::vector<FieldBeam> beams;
    beams.reserve(wavelengths.size());
    for (double nm : wavelengths) {
        beams.push_back(trace_field_beam(system, first_order, field, nm, rings));
    }
    return polychromatic_spot(beams, weights, image_z);
}

}  // namespace lenslab
