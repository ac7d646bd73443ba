#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "geometry/lens/lens_surface.h"

namespace lenslab {

namespace {

constexpr int kFitPoints = 8;

// Fits z(u) = b1 u + b2 u^2 + ... + b8 u^8, u = r^2 / u_max, through the sag at eight
// Chebyshev points of (0, 1] (sag(0) = 0 is the ninth condition, built in): Gaussian
// elimination with partial pivoting on the 8x8 Vandermonde system.
std::array<double, kFitPoints> fit_in_r_squared(const LensSurface& s, double r_max) {
    std::array<std::array<double, kFitPoints + 1>, kFitPoints> m{};
    for (int j = 0; j < kFitPoints; ++j) {
        const double t = 0.5 * (1.0 - std::cos(std::numbers::pi * (j + 0.5) / kFitPoints));
        double power = 1.0;
        for (int k = 0; k < kFitPoints; ++k) m[j][k] = power *= t;
        m[j][kFitPoints] = s.sag(r_max * std::sqrt(t));
    }
    for (int col = 0; col < kFitPoints; ++col) {
        int pivot = col;
        for (int row = col + 1; row < kFitPoints; ++row) {
            if (std::abs(m[row][col]) > std::abs(m[pivot][col])) pivot = row;
        }
        std::swap(m[col], m[pivot]);
        for (int row = col + 1; row < kFitPoints; ++row) {
            const double f = m[row][col] / m[col][col];
            for (int k = col; k <= kFitPoints; ++k) m[row][k] -= f * m[col][k];
        }
    }
    std::array<double, kFitPoints> b{};
    for (int row = kFitPoints - 1; row >= 0; --row) {
        double sum = m[row][kFitPoints];
        for (int k = row + 1; k < kFitPoints; ++k) sum -= m[row][k] * b[k];
        b[row] = sum / m[row][row];
    }
    return b;
}

VertexSag coefficients(const LensSurface& s, double r_max) {
    const std::array<double, kFitPoints> b = fit_in_r_squared(s, r_max);
    const double u_max = r_max * r_max;
    return {2.0 * b[0] / u_max, b[1] / (u_max * u_max)};
}

}  // namespace

VertexSag fit_vertex_sag(const LensSurface& surface, double semi_diameter) {
    // The series converges within about a radius of curvature of the axis: a first fit
    // over a quarter of the semi-diameter finds the curvature, the second spans a quarter
    // of the radius of curvature (or the whole semi-diameter, when that is less), far enough
    // out that the r^4 term stands above the rounding of the sag, close enough in that the
    // degree-8 polynomial holds the rest of the series.
    const VertexSag first = coefficients(surface, 0.25 * semi_diameter);
    const double r_max = std::abs(first.curvature) * semi_diameter > 0.25
                             ? 0.25 / std::abs(first.curvature)
                             : semi_diameter;
    return coefficients(surface, r_max);
}

}  // namespace lenslab
