#include "analysis/aberrations/polychromatic_spot.h"

#include <algorithm>
#include <cmath>

#include "analysis/system/real_ray.h"

namespace lenslab {

PolychromaticSpot polychromatic_spot(const std::vector<FieldBeam>& beams,
                                     const std::vector<double>& weights, double image_z,
                                     std::vector<double>* deviations) {
    PolychromaticSpot spot;
    // The weighted centroid, then the mean square distance from it (two passes: E[x²] - E[x]²
    // would lose the spot's few microns to rounding far off the axis, where x is ~20 mm).
    double w_sum = 0, sx = 0, sy = 0;
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
        }
    }
    if (!(w_sum > 0)) {
        spot.rms_radius = NAN;
        return spot;
    }
    spot.centroid_x = sx / w_sum;
    spot.centroid_y = sy / w_sum;
    double mean_square = 0;
    for (size_t i = 0; i < beams.size(); ++i) {
        const double scale = std::sqrt((weights.empty() ? 1.0 : weights[i]) / w_sum);
        for (const ExitRay& r : beams[i].rays) {
            const Vec3 p = at_plane(r.point, r.direction, image_z);
            const double dx = scale * (p.x - spot.centroid_x), dy = scale * (p.y - spot.centroid_y);
            mean_square += dx * dx + dy * dy;
            if (deviations) {
                deviations->push_back(dx);
                deviations->push_back(dy);
            }
        }
    }
    spot.rms_radius = std::sqrt(mean_square);
    return spot;
}

PolychromaticSpot polychromatic_rms_spot(const OpticalSystem& system, const FirstOrder& first_order,
                                         double field, const std::vector<double>& wavelengths,
                                         const std::vector<double>& weights, int rings,
                                         double image_z, std::vector<double>* deviations) {
    std::vector<FieldBeam> beams;
    beams.reserve(wavelengths.size());
    for (double nm : wavelengths) {
        beams.push_back(trace_field_beam(system, first_order, field, nm, rings));
    }
    return polychromatic_spot(beams, weights, image_z, deviations);
}

}  // namespace lenslab
