#pragma once
// Law of reflection and Snell's law in vector form (Hecht, Optics, section 4.4;
// pbrt-v4 section 9.3 derives the same vector form).

#include <cmath>
#include <optional>

#include "math/vec3.h"

namespace lenslab {

// Mirror `d` about the plane with unit normal `n` (either orientation).
inline Vec3 reflect(const Vec3& d, const Vec3& n) { return d - n * (2.0 * dot(d, n)); }

// Refract unit direction `d` through a surface with unit normal `n` facing the incident side
// (dot(d, n) < 0); eta_ratio = eta_incident / eta_transmitted. Empty on total internal
// reflection, where n1 sin(a) = n2 sin(b) has no solution.
inline std::optional<Vec3> refract(const Vec3& d, const Vec3& n, double eta_ratio) {
    const double cos_i = -dot(d, n);
    const double sin_t2 = eta_ratio * eta_ratio * std::max(0.0, 1.0 - cos_i * cos_i);
    if (sin_t2 >= 1.0) return std::nullopt;
    const double cos_t = std::sqrt(1.0 - sin_t2);
    return normalize(d * eta_ratio + n * (eta_ratio * cos_i - cos_t));
}

}  // namespace lenslab
