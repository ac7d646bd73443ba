#include "geometry/lens/lens_surface.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lenslab {

namespace {

// Sampling density: along one radius for a surface of revolution (dense enough to catch two
// faces crossing between samples for any smooth sag: spheres, conics, low-order aspheres),
// or a polar grid for z(x, y).
constexpr int kSymmetricRadii = 512;
constexpr int kGridRadii = 128;
constexpr int kGridAngles = 128;

struct Grid {
    int radii;   // samples at r_i = a i / radii, i = 0..radii
    int angles;  // at phi_j = 2 pi j / angles; 1 for a surface of revolution (phi = 0)
};

Grid grid_for(bool symmetric) {
    return symmetric ? Grid{kSymmetricRadii, 1} : Grid{kGridRadii, kGridAngles};
}

DiscPoint grid_point(const Grid& g, double a, int i, int j) {
    const double r = a * i / g.radii;
    if (g.angles == 1) return {r, 0.0};
    // Snapped so that points on the axes are exact (messages show (0, 10), not (6e-16, 10)).
    const double phi = 2.0 * std::numbers::pi * j / g.angles;
    auto snap = [](double v) { return std::abs(v) < 1e-12 ? 0.0 : v; };
    return {r * snap(std::cos(phi)), r * snap(std::sin(phi))};
}

}  // namespace

std::vector<DiscPoint> disc_sample_points(double semi_diameter, bool symmetric) {
    const Grid g = grid_for(symmetric);
    std::vector<DiscPoint> points{{0.0, 0.0}};
    for (int i = 1; i <= g.radii; ++i) {
        for (int j = 0; j < g.angles; ++j) points.push_back(grid_point(g, semi_diameter, i, j));
    }
    return points;
}

SurfaceSpan measure_span(const LensSurface& surface, double a) {
    SurfaceSpan span;
    span.semi_diameter = a;
    const Grid g = grid_for(surface.is_rotationally_symmetric());
    const double dr = a / g.radii;
    const double dphi = 2.0 * std::numbers::pi / g.angles;
    // z[i][j] on the grid, row by row; the centre is one point for every angle.
    std::vector<double> z(size_t(g.radii + 1) * g.angles);
    auto at = [&](int i, int j) -> double& { return z[size_t(i) * g.angles + j]; };
    const double z0 = surface.sag_xy(0.0, 0.0);
    double z_min = z0, z_max = z0, radial = 0, tangential = 0, largest_step = 0;
    for (int i = 0; i <= g.radii; ++i) {
        for (int j = 0; j < g.angles; ++j) {
            const DiscPoint p = grid_point(g, a, i, j);
            const double v = i == 0 ? z0 : surface.sag_xy(p.x, p.y);
            if (!std::isfinite(v)) return SurfaceSpan{a};  // unbounded: the lens refuses it anyway
            at(i, j) = v;
            z_min = std::min(z_min, v);
            z_max = std::max(z_max, v);
            if (i > 0) {
                const double step = std::abs(v - at(i - 1, j));
                radial = std::max(radial, step / dr);
                largest_step = std::max(largest_step, step);
            }
            if (i > 0 && j > 0) {
                const double step = std::abs(v - at(i, j - 1));
                tangential = std::max(tangential, step / (a * i / g.radii * dphi));
                largest_step = std::max(largest_step, step);
            }
        }
    }
    // Between two samples a smooth sag strays beyond them by less than one step's change;
    // the slope of a chord underestimates the largest slope it spans, hence the margins.
    const double pad = largest_step + 1e-9 * std::max({1.0, a, std::abs(z_min), std::abs(z_max)});
    span.z_min = z_min - pad;
    span.z_max = z_max + pad;
    span.max_slope = 1.5 * std::hypot(radial, tangential) + 1e-12;
    return span;
}

SurfaceSpan intersect_span(const LensSurface& surface, double a) {
    return surface.intersect_reads_bounds() ? measure_span(surface, a) : SurfaceSpan{a};
}

}  // namespace lenslab
