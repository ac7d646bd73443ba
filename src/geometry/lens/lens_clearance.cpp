#include "geometry/lens/lens_clearance.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace lenslab {

namespace {

// Many more radii than a lens samples for itself: the pair is checked once, when read. Faces
// that are not surfaces of revolution take a polar grid of 1024 radii by 128 angles.
constexpr int kClearanceRadii = 4096;
constexpr int kClearanceRadiiPolar = 1024;
constexpr int kClearanceAngles = 128;

struct ClearanceProbe {
    const LensSurface& back;
    const LensSurface& front;
    double spacing;
    // NaN where either sag is undefined, so that the comparisons below skip it.
    double at(double x, double y) const { return spacing + front.sag_xy(x, y) - back.sag_xy(x, y); }
};

void keep_if_smaller(Clearance& best, double gap, double x, double y) {
    if (gap < best.gap) best = {gap, {x, y}};
}

// Golden-section search for the smallest clearance along the ray from the axis at angle
// (c, s), for radii in [lo, hi]: finds a dip narrower than the sample spacing.
void refine_along_radius(const ClearanceProbe& probe, double c, double s, double lo, double hi,
                         Clearance& best) {
    const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
    double a = lo, b = hi;
    double r1 = b - ratio * (b - a), r2 = a + ratio * (b - a);
    double g1 = probe.at(r1 * c, r1 * s), g2 = probe.at(r2 * c, r2 * s);
    for (int i = 0; i < 100 && b - a > 1e-15 * std::max(1.0, hi); ++i) {
        if (g1 < g2 || std::isnan(g2)) {
            b = r2;
            r2 = r1;
            g2 = g1;
            r1 = b - ratio * (b - a);
            g1 = probe.at(r1 * c, r1 * s);
        } else {
            a = r1;
            r1 = r2;
            g1 = g2;
            r2 = a + ratio * (b - a);
            g2 = probe.at(r2 * c, r2 * s);
        }
        keep_if_smaller(best, g1, r1 * c, r1 * s);
        keep_if_smaller(best, g2, r2 * c, r2 * s);
    }
}

}  // namespace

Clearance smallest_clearance(const LensSurface& back, const LensSurface& front, double spacing,
                             double semi_diameter) {
    const ClearanceProbe probe{back, front, spacing};
    const bool symmetric = back.is_rotationally_symmetric() && front.is_rotationally_symmetric();
    const int angles = symmetric ? 1 : kClearanceAngles;
    const int radii = symmetric ? kClearanceRadii : kClearanceRadiiPolar;
    const double dr = semi_diameter / radii;
    Clearance best{std::numeric_limits<double>::infinity(), {0, 0}};
    keep_if_smaller(best, probe.at(0, 0), 0, 0);
    int worst_radius = 0, worst_angle = 0;
    for (int j = 0; j < angles; ++j) {
        const double phi = 2.0 * std::numbers::pi * j / angles;
        const double c = std::cos(phi), s = std::sin(phi);
        for (int i = 1; i <= radii; ++i) {
            // The last radius is exactly the rim, not a rounded multiple of dr.
            const double r = i == radii ? semi_diameter : i * dr;
            const double before = best.gap;
            keep_if_smaller(best, probe.at(r * c, r * s), r * c, r * s);
            if (best.gap < before) {
                worst_radius = i;
                worst_angle = j;
            }
        }
    }
    const double phi = 2.0 * std::numbers::pi * worst_angle / angles;
    const double lo = std::max(0, worst_radius - 1) * dr;
    const double hi = std::min(semi_diameter, (worst_radius + 1) * dr);
    refine_along_radius(probe, std::cos(phi), std::sin(phi), lo, hi, best);
    return best;
}

}  // namespace lenslab
