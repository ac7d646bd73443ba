#pragma once
// A flat surface's own coordinates: an origin and three orthonormal axes, u and v in the
// plane and n its normal (u, v, n right-handed). Discs, rectangles and detectors use it to
// say where a point lies on the surface.

#include <cmath>
#include <optional>

#include "math/ray.h"

namespace lenslab {

struct PlaneFrame {
    Vec3 origin;
    Vec3 u, v, n;  // unit; u x v = n

    // The frame whose v is `up` made perpendicular to `normal` (as a camera's up): seen from
    // the side the normal points to, u runs right and v up. `normal` and `up` must be unit
    // and not parallel.
    static PlaneFrame from_normal_up(const Vec3& origin, const Vec3& normal, const Vec3& up) {
        const Vec3 u = normalize(cross(up, normal));
        return {origin, u, cross(normal, u), normal};
    }

    // (u, v) coordinates of a point of the plane.
    double u_of(const Vec3& p) const { return dot(p - origin, u); }
    double v_of(const Vec3& p) const { return dot(p - origin, v); }
    Vec3 at(double cu, double cv) const { return origin + u * cu + v * cv; }

    // Distance along the ray to the plane, if it meets it inside (t_min, t_max).
    std::optional<double> ray_t(const Ray& ray, double t_min, double t_max) const {
        const double denom = dot(ray.direction, n);
        if (std::abs(denom) < 1e-300) return std::nullopt;  // parallel (or NaN)
        const double t = dot(origin - ray.origin, n) / denom;
        if (!in_range(t, t_min, t_max)) return std::nullopt;
        return t;
    }
};

// Default `up` of a flat surface: world +y, or -z when the normal is (nearly) vertical, so
// a floor seen from above has u along +x and v along -z.
inline Vec3 default_plane_up(const Vec3& normal) {
    return length(cross(Vec3{0, 1, 0}, normal)) > 1e-6 ? Vec3{0, 1, 0} : Vec3{0, 0, -1};
}

}  // namespace lenslab
