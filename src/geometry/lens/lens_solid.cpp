#include "geometry/lens/lens_solid.h"

#include <cmath>
#include <sstream>

#include "geometry/lens/spherical_surface.h"
#include "math/quadratic.h"

namespace lenslab {

namespace {

// Axial gap between the two faces at radius r for a prescription not yet built.
double gap_at(const LensPrescription& p, double r) {
    return p.thickness + p.back->sag(r) - p.front->sag(r);
}

// Radii at which the face gap is checked: dense enough to catch surfaces crossing between
// samples for any smooth sag (spheres, conics, low-order aspheres).
constexpr int kGapSamples = 512;

}  // namespace

LensSolid::LensSolid(LensPrescription p) : m_p(std::move(p)), m_frame(Frame::from_axis(m_p.axis)) {}

std::optional<LensSolid::Problem> LensSolid::check_prescription(const LensPrescription& p) {
    std::ostringstream msg;
    msg.precision(10);
    if (!(p.thickness > 0)) {
        msg << "must be > 0, got " << p.thickness;
        return Problem{"thickness", msg.str()};
    }
    if (!(p.diameter > 0)) {
        msg << "must be > 0, got " << p.diameter;
        return Problem{"diameter", msg.str()};
    }
    const double a = 0.5 * p.diameter;
    for (const auto& [name, s] : {std::pair{"front", p.front}, std::pair{"back", p.back}}) {
        if (a > s->max_semi_diameter()) {
            msg << "a " << s->describe() << " surface cannot span the lens diameter "
                << p.diameter << " (its largest diameter is " << 2 * s->max_semi_diameter()
                << ")";
            return Problem{name, msg.str()};
        }
    }
    // The gap may close to exactly zero at the rim (a knife edge) but must not go negative.
    const double tolerance = 1e-12 * std::max(1.0, p.thickness);
    double worst_gap = 0.0, worst_r = 0.0;
    for (int i = 0; i <= kGapSamples; ++i) {
        const double r = a * i / kGapSamples;
        const double gap = gap_at(p, r);
        if (gap < worst_gap) {
            worst_gap = gap;
            worst_r = r;
        }
    }
    if (worst_gap < -tolerance) {
        msg << "the lens surfaces cross inside the diameter: at " << worst_r
            << " from the axis the back surface lies " << -worst_gap
            << " in front of the front surface; the centre thickness must be at least "
            << p.thickness - worst_gap << " for diameter " << p.diameter
            << " (or reduce the diameter)";
        return Problem{"thickness", msg.str()};
    }
    return std::nullopt;
}

LensPrescription LensSolid::symmetric_biconvex(const Vec3& centre, const Vec3& axis,
                                               double curvature_radius,
                                               double aperture_radius) {
    const auto front = std::make_shared<SphericalSurface>(curvature_radius);
    const double sag = front->sag(aperture_radius);
    return {centre, axis, 2.0 * sag, 2.0 * aperture_radius, front,
            std::make_shared<SphericalSurface>(-curvature_radius)};
}

double LensSolid::edge_thickness() const {
    const double a = 0.5 * m_p.diameter;
    return back_z(a) - front_z(a);
}

bool LensSolid::contains(const Vec3& world) const {
    const Vec3 p = m_frame.to_local(world - m_p.centre);
    const double r = std::hypot(p.x, p.y);
    return r <= 0.5 * m_p.diameter && p.z >= front_z(r) && p.z <= back_z(r);
}

bool LensSolid::intersect(const Ray& world_ray, double t_min, double t_max,
                          SurfaceHit& hit) const {
    const Ray ray{m_frame.to_local(world_ray.origin - m_p.centre),
                  m_frame.to_local(world_ray.direction)};
    const double a = 0.5 * m_p.diameter;
    const double half_t = 0.5 * m_p.thickness;

    double best_t = t_max;
    Vec3 best_normal;
    bool found = false;

    // The solid's boundary is three patches (front face, back face, rim) that meet exactly, so
    // the nearest crossing of any patch is where the ray enters or leaves the solid.
    double t;
    const Ray front_ray{{ray.origin.x, ray.origin.y, ray.origin.z + half_t}, ray.direction};
    if (m_p.front->intersect(front_ray, a, t_min, best_t, t)) {
        best_t = t;
        best_normal = -m_p.front->normal(front_ray.at(t));
        found = true;
    }
    const Ray back_ray{{ray.origin.x, ray.origin.y, ray.origin.z - half_t}, ray.direction};
    if (m_p.back->intersect(back_ray, a, t_min, best_t, t)) {
        best_t = t;
        best_normal = m_p.back->normal(back_ray.at(t));
        found = true;
    }

    // Rim: the cylinder x^2 + y^2 = a^2 between the faces' edges.
    const double z_lo = front_z(a), z_hi = back_z(a);
    const double pad = kSeamTolerance * std::max(1.0, a);
    double roots[2];
    if (z_hi - z_lo > 0 &&
        solve_half_quadratic(ray.direction.x * ray.direction.x + ray.direction.y * ray.direction.y,
                             ray.origin.x * ray.direction.x + ray.origin.y * ray.direction.y,
                             ray.origin.x * ray.origin.x + ray.origin.y * ray.origin.y - a * a,
                             roots[0], roots[1])) {
        for (double tc : roots) {
            if (!in_range(tc, t_min, best_t)) continue;
            const Vec3 p = ray.at(tc);
            if (p.z < z_lo - pad || p.z > z_hi + pad) continue;
            best_t = tc;
            best_normal = Vec3{p.x, p.y, 0.0} / a;
            found = true;
            break;
        }
    }
    if (!found) return false;

    hit.t = best_t;
    hit.point = world_ray.at(best_t);
    hit.normal = normalize(m_frame.to_world(best_normal));
    return true;
}

Aabb LensSolid::bounds() const {
    const double a = 0.5 * m_p.diameter;
    double z_lo = front_z(0), z_hi = back_z(0);
    for (int i = 1; i <= kGapSamples; ++i) {
        const double r = a * i / kGapSamples;
        z_lo = std::min(z_lo, front_z(r));
        z_hi = std::max(z_hi, back_z(r));
    }
    const double pad = 1e-6 * std::max(1.0, a);
    Aabb box;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 local{(corner & 1) ? a + pad : -a - pad, (corner & 2) ? a + pad : -a - pad,
                         (corner & 4) ? z_hi + pad : z_lo - pad};
        box.expand(m_p.centre + m_frame.to_world(local));
    }
    return box;
}

}  // namespace lenslab
