#pragma once
// Axis-aligned bounding box with the slab test (Kay & Kajiya 1986).

#include <limits>

#include "math/ray.h"

namespace lenslab {

struct Aabb {
    Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
            std::numeric_limits<double>::infinity()};
    Vec3 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
            -std::numeric_limits<double>::infinity()};

    void expand(const Vec3& p) {
        lo = min(lo, p);
        hi = max(hi, p);
    }
    void expand(const Aabb& b) {
        lo = min(lo, b.lo);
        hi = max(hi, b.hi);
    }
    Vec3 centre() const { return (lo + hi) * 0.5; }
    Vec3 extent() const { return hi - lo; }
    bool empty() const { return lo.x > hi.x; }
    // Inside or on the box (never, for an empty box).
    bool contains(const Vec3& p) const {
        return p.x >= lo.x && p.y >= lo.y && p.z >= lo.z && p.x <= hi.x && p.y <= hi.y &&
               p.z <= hi.z;
    }

    // inv_dir = 1 / ray.direction componentwise (infinities are fine). Conservative: the far
    // slab distance is enlarged by its worst rounding error, 2 gamma(3) (Ize 2013, "Robust BVH
    // Ray Traversal", JCGT 2(2); pbrt-v4 Bounds3::IntersectP), so a ray through a corner
    // or edge shared by two boxes (a mesh vertex on both) is never refused by both.
    bool hit(const Ray& ray, const Vec3& inv_dir, double t_min, double t_max) const {
        constexpr double kEps = std::numeric_limits<double>::epsilon() * 0.5;
        constexpr double kFarScale = 1.0 + 2.0 * (3.0 * kEps / (1.0 - 3.0 * kEps));
        for (int a = 0; a < 3; ++a) {
            double t0 = (lo[a] - ray.origin[a]) * inv_dir[a];
            double t1 = (hi[a] - ray.origin[a]) * inv_dir[a];
            if (inv_dir[a] < 0) std::swap(t0, t1);
            t1 *= kFarScale;
            // NaN (0 * inf) comparisons fail, which keeps the interval: conservative.
            t_min = t0 > t_min ? t0 : t_min;
            t_max = t1 < t_max ? t1 : t_max;
            if (t_max < t_min) return false;
        }
        return true;
    }
};

// Calls `visit(p)` at the n x n x n points spaced evenly over `box`, corners included (n >= 2),
// until it returns false; false then, true when every point was visited. The grid on which
// typed formulas are checked before rendering (implicit solids, medium densities).
template <class Visit>
bool for_each_grid_point(const Aabb& box, int n, Visit&& visit) {
    const Vec3 e = box.extent();
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            for (int k = 0; k < n; ++k) {
                if (!visit(box.lo + Vec3{e.x * i, e.y * j, e.z * k} / (n - 1))) return false;
            }
        }
    }
    return true;
}

}  // namespace lenslab
