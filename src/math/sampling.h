#pragma once
// Warping uniform numbers to directions and points (pbrt-v4 "Sampling Functions", Ch. A.5).

#include <cmath>
#include <numbers>

#include "math/vec3.h"

namespace lenslab {

// Uniform point on the unit disc, concentric mapping (Shirley & Chiu 1997): keeps strata.
inline void sample_disc_concentric(double u1, double u2, double& x, double& y) {
    const double a = 2.0 * u1 - 1.0, b = 2.0 * u2 - 1.0;
    if (a == 0.0 && b == 0.0) {
        x = y = 0.0;
        return;
    }
    double r, phi;
    if (std::abs(a) > std::abs(b)) {
        r = a;
        phi = (std::numbers::pi / 4.0) * (b / a);
    } else {
        r = b;
        phi = std::numbers::pi / 2.0 - (std::numbers::pi / 4.0) * (a / b);
    }
    x = r * std::cos(phi);
    y = r * std::sin(phi);
}

// Cosine-weighted direction about +z; pdf = cos(theta) / pi.
inline Vec3 sample_cosine_hemisphere(double u1, double u2) {
    double x, y;
    sample_disc_concentric(u1, u2, x, y);
    return {x, y, std::sqrt(std::max(0.0, 1.0 - x * x - y * y))};
}

// Uniform direction on the unit sphere; pdf = 1 / (4 pi).
inline Vec3 sample_uniform_sphere(double u1, double u2) {
    const double z = 1.0 - 2.0 * u1;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = 2.0 * std::numbers::pi * u2;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// Uniform direction in the cone of half-angle acos(cos_max) about +z;
// pdf = 1 / (2 pi (1 - cos_max)).
inline Vec3 sample_uniform_cone(double u1, double u2, double cos_max) {
    const double cos_t = 1.0 - u1 * (1.0 - cos_max);
    const double sin_t = std::sqrt(std::max(0.0, 1.0 - cos_t * cos_t));
    const double phi = 2.0 * std::numbers::pi * u2;
    return {sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t};
}

}  // namespace lenslab
