#include "scene/photon_targets.h"

#include <cmath>

#include "math/constants.h"
#include "math/frame.h"
#include "math/sampling.h"

namespace lenslab {

namespace {

struct Cone {
    Vec3 axis;
    double cos_max;      // -1: the whole sphere of directions
    double solid_angle;  // 2 pi (1 - cos_max)
};

// The cone a sphere subtends from `from`; the whole sphere when `from` is inside it.
Cone cone_of(const BoundingSphere& s, const Vec3& from) {
    const Vec3 to_centre = s.centre - from;
    const double d2 = length_squared(to_centre);
    const double r2 = s.radius * s.radius;
    if (d2 <= r2) return {{0, 0, 1}, -1.0, 4.0 * kPi};
    const double cos_max = std::sqrt(1.0 - r2 / d2);
    // 1 - cos_max without cancellation for small, distant targets.
    return {to_centre / std::sqrt(d2), cos_max, 2.0 * kPi * (r2 / d2) / (1.0 + cos_max)};
}

// Picks the entry whose share of `total` holds u * total.
template <class Item, class Measure>
size_t pick(const std::vector<Item>& items, double u, double total, Measure measure) {
    double target = u * total;
    for (size_t i = 0; i + 1 < items.size(); ++i) {
        target -= measure(items[i]);
        if (target < 0.0) return i;
    }
    return items.size() - 1;
}

// The disc a sphere casts along `normal` on the plane through `origin`; false when the
// sphere lies wholly behind the plane.
bool disc_of(const BoundingSphere& s, const Vec3& origin, const Vec3& normal, Vec3& centre) {
    const double along = dot(s.centre - origin, normal);
    if (along < -s.radius) return false;
    centre = s.centre - normal * along;
    return true;
}

}  // namespace

double PhotonTargets::solid_angle(const Vec3& from) const {
    double total = 0;
    for (const BoundingSphere& s : m_spheres) total += cone_of(s, from).solid_angle;
    return total;
}

double PhotonTargets::plane_area(const Vec3& origin, const Vec3& normal) const {
    double total = 0;
    Vec3 centre;
    for (const BoundingSphere& s : m_spheres) {
        if (disc_of(s, origin, normal, centre)) total += kPi * s.radius * s.radius;
    }
    return total;
}

bool PhotonTargets::sample_direction(const Vec3& from, double u0, double u1, double u2,
                                     double max_solid_angle, Vec3& dir, double& pdf) const {
    // Few targets in a scene: the cones are rebuilt for each sample rather than stored (a
    // point on an emitting sphere sees them from a new place each time).
    thread_local std::vector<Cone> cones;
    cones.clear();
    double total = 0;
    for (const BoundingSphere& s : m_spheres) {
        cones.push_back(cone_of(s, from));
        total += cones.back().solid_angle;
    }
    if (cones.empty() || total >= max_solid_angle) return false;
    const size_t chosen = pick(cones, u0, total, [](const Cone& c) { return c.solid_angle; });
    const Cone& c = cones[chosen];
    dir = c.cos_max <= -1.0
              ? sample_uniform_sphere(u1, u2)
              : Frame::from_axis(c.axis).to_world(sample_uniform_cone(u1, u2, c.cos_max));
    int holding = 1;  // the chosen cone, whatever rounding says
    for (size_t i = 0; i < cones.size(); ++i) {
        if (i != chosen && dot(dir, cones[i].axis) >= cones[i].cos_max) ++holding;
    }
    pdf = holding / total;
    return true;
}

bool PhotonTargets::sample_plane_point(const Vec3& origin, const Vec3& normal, double u0, double u1,
                                       double u2, double max_area, Vec3& point, double& pdf) const {
    struct Disc {
        Vec3 centre;
        double radius, area;
    };
    thread_local std::vector<Disc> discs;
    discs.clear();
    double total = 0;
    Vec3 centre;
    for (const BoundingSphere& s : m_spheres) {
        if (!disc_of(s, origin, normal, centre)) continue;
        discs.push_back({centre, s.radius, kPi * s.radius * s.radius});
        total += discs.back().area;
    }
    if (discs.empty() || total >= max_area) return false;
    const size_t chosen = pick(discs, u0, total, [](const Disc& d) { return d.area; });
    double x, y;
    sample_disc_concentric(u1, u2, x, y);
    const Frame f = Frame::from_axis(normal);
    point = discs[chosen].centre + (f.u * x + f.v * y) * discs[chosen].radius;
    int holding = 1;
    for (size_t i = 0; i < discs.size(); ++i) {
        if (i != chosen &&
            length_squared(point - discs[i].centre) <= discs[i].radius * discs[i].radius) {
            ++holding;
        }
    }
    pdf = holding / total;
    return true;
}

}  // namespace lenslab
