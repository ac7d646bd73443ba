#include "geometry/lens/lens_solid.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "geometry/lens/spherical_surface.h"
#include "math/quadratic.h"
#include "util/error.h"
#include "util/format_number.h"

namespace lenslab {

Frame lens_frame(const LensPrescription& p) {
    const Vec3 x = p.x_axis - p.axis * dot(p.x_axis, p.axis);
    if (!(length(x) > 1e-12)) return Frame::from_axis(p.axis);
    const Vec3 u = normalize(x);
    return {u, cross(p.axis, u), p.axis};
}

namespace {

std::string where(const DiscPoint& q, bool symmetric) {
    if (symmetric) return "r = " + format_number(std::hypot(q.x, q.y));
    return "(x, y) = (" + format_number(q.x) + ", " + format_number(q.y) + ")";
}

}  // namespace

LensSolid::LensSolid(LensPrescription p) : m_p(std::move(p)), m_frame(lens_frame(m_p)) {
    const double a = 0.5 * m_p.diameter;
    m_front_span = intersect_span(*m_p.front, a);
    m_back_span = intersect_span(*m_p.back, a);
    m_rim_lo = front_z(a);
    m_rim_hi = back_z(a);
}

bool LensSolid::symmetric() const {
    return m_p.front->is_rotationally_symmetric() && m_p.back->is_rotationally_symmetric();
}

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
    if (length(p.x_axis) > 0 && length(cross(p.x_axis, p.axis)) < 1e-9 * length(p.x_axis)) {
        return Problem{"x_axis", "must not be parallel to the axis"};
    }
    const double a = 0.5 * p.diameter;
    for (const auto& [name, s] : {std::pair{"front", p.front}, std::pair{"back", p.back}}) {
        if (a > s->max_semi_diameter()) {
            msg << with_article(s->describe()) << " surface cannot span the lens diameter "
                << p.diameter << " (its largest diameter is " << 2 * s->max_semi_diameter() << ")";
            return Problem{name, msg.str()};
        }
    }
    const bool symmetric =
        p.front->is_rotationally_symmetric() && p.back->is_rotationally_symmetric();
    const std::vector<DiscPoint> points = disc_sample_points(a, symmetric);
    // Typed formulas can be undefined (sqrt of a negative) or infinite somewhere: refuse
    // that here rather than render holes. The sags are kept for the gaps below.
    std::vector<double> sags[2];
    const std::pair<const char*, const LensSurface*> faces[] = {{"front", p.front.get()},
                                                                {"back", p.back.get()}};
    for (int f = 0; f < 2; ++f) {
        const auto& [name, s] = faces[f];
        sags[f].reserve(points.size());
        for (const DiscPoint& q : points) {
            sags[f].push_back(s->sag_xy(q.x, q.y));
            if (std::isfinite(sags[f].back())) continue;
            const std::string why = s->why_undefined(q.x, q.y);
            msg << "sag undefined at " << where(q, symmetric) << " inside the diameter"
                << (why.empty() ? "" : " (" + why + ")");
            return Problem{name, msg.str()};
        }
    }
    // The gap may close to exactly zero at the rim (a knife edge) but must not go negative.
    const double tolerance = 1e-12 * std::max(1.0, p.thickness);
    double worst_gap = 0.0;
    DiscPoint worst{0, 0};
    for (size_t i = 0; i < points.size(); ++i) {
        const DiscPoint& q = points[i];
        const double gap = p.thickness + sags[1][i] - sags[0][i];
        if (gap < worst_gap) {
            worst_gap = gap;
            worst = q;
        }
    }
    if (worst_gap < -tolerance) {
        msg << "the lens surfaces cross inside the diameter: at ";
        if (symmetric) {
            msg << std::hypot(worst.x, worst.y) << " from the axis";
        } else {
            msg << where(worst, false);
        }
        msg << " the back surface lies " << -worst_gap
            << " in front of the front surface; the centre thickness must be at least "
            << p.thickness - worst_gap << " for diameter " << p.diameter
            << " (or reduce the diameter)";
        return Problem{"thickness", msg.str()};
    }
    return std::nullopt;
}

LensPrescription LensSolid::symmetric_biconvex(const Vec3& centre, const Vec3& axis,
                                               double curvature_radius, double aperture_radius) {
    const auto front = std::make_shared<SphericalSurface>(curvature_radius);
    const double sag = front->sag(aperture_radius);
    return {centre,    axis,
            2.0 * sag, 2.0 * aperture_radius,
            front,     std::make_shared<SphericalSurface>(-curvature_radius)};
}

double LensSolid::edge_thickness() const {
    const double a = 0.5 * m_p.diameter;
    if (symmetric()) return back_z(a) - front_z(a);
    double thinnest = INFINITY;
    for (const DiscPoint& q : disc_sample_points(a, false)) {
        if (std::abs(std::hypot(q.x, q.y) - a) > 1e-9 * a) continue;  // rim points only
        thinnest = std::min(thinnest, back_z(q.x, q.y) - front_z(q.x, q.y));
    }
    return thinnest;
}

bool LensSolid::contains(const Vec3& world) const {
    const Vec3 p = m_frame.to_local(world - m_p.centre);
    return std::hypot(p.x, p.y) <= 0.5 * m_p.diameter && p.z >= front_z(p.x, p.y) &&
           p.z <= back_z(p.x, p.y);
}

bool LensSolid::intersect(const Ray& world_ray, double t_min, double t_max, SurfaceHit& hit) const {
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
    if (m_p.front->intersect(front_ray, m_front_span, t_min, best_t, t)) {
        best_t = t;
        best_normal = -m_p.front->normal(front_ray.at(t));
        found = true;
    }
    const Ray back_ray{{ray.origin.x, ray.origin.y, ray.origin.z - half_t}, ray.direction};
    if (m_p.back->intersect(back_ray, m_back_span, t_min, best_t, t)) {
        best_t = t;
        best_normal = m_p.back->normal(back_ray.at(t));
        found = true;
    }

    // Rim: the cylinder x^2 + y^2 = a^2 between the faces' edges. For surfaces of revolution
    // the edges are circles at fixed z; otherwise the z-range is taken where the ray meets it.
    const bool sym = symmetric();
    const double pad = kSeamTolerance * std::max(1.0, a);
    double roots[2];
    if ((!sym || m_rim_hi - m_rim_lo > 0) &&
        solve_half_quadratic(ray.direction.x * ray.direction.x + ray.direction.y * ray.direction.y,
                             ray.origin.x * ray.direction.x + ray.origin.y * ray.direction.y,
                             ray.origin.x * ray.origin.x + ray.origin.y * ray.origin.y - a * a,
                             roots[0], roots[1])) {
        for (double tc : roots) {
            if (!in_range(tc, t_min, best_t)) continue;
            const Vec3 p = ray.at(tc);
            const double z_lo = sym ? m_rim_lo : front_z(p.x, p.y);
            const double z_hi = sym ? m_rim_hi : back_z(p.x, p.y);
            if (!(z_hi - z_lo > 0) || p.z < z_lo - pad || p.z > z_hi + pad) continue;
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

const LensSolid::Slab& LensSolid::slab() const {
    std::call_once(m_slab->measured, [this] {
        // A closed-form face's intersect_span has no z-range: measure it now.
        const double a = 0.5 * m_p.diameter;
        const auto spanned = [a](const LensSurface& face, const SurfaceSpan& kept) {
            return face.intersect_reads_bounds() ? kept : measure_span(face, a);
        };
        m_slab->z_lo = -0.5 * m_p.thickness + spanned(*m_p.front, m_front_span).z_min;
        m_slab->z_hi = 0.5 * m_p.thickness + spanned(*m_p.back, m_back_span).z_max;
    });
    return *m_slab;
}

BoundingSphere LensSolid::bounding_sphere() const {
    const double a = 0.5 * m_p.diameter;
    const double z_lo = slab().z_lo;
    const double z_hi = slab().z_hi;
    const double half = 0.5 * (z_hi - z_lo);
    const double pad = 1e-6 * std::max(1.0, a);
    return {m_p.centre + m_frame.to_world({0, 0, 0.5 * (z_lo + z_hi)}),
            std::sqrt(a * a + half * half) + pad};
}

Aabb LensSolid::bounds() const {
    const double a = 0.5 * m_p.diameter;
    // The spans' slabs hold every point of the faces (they are padded for the sampling).
    const double z_lo = slab().z_lo;
    const double z_hi = slab().z_hi;
    const double pad = 1e-6 * std::max(1.0, a);
    Aabb box;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 local{(corner & 1) ? a + pad : -a - pad, (corner & 2) ? a + pad : -a - pad,
                         (corner & 4) ? z_hi + pad : z_lo - pad};
        box.expand(m_p.centre + m_frame.to_world(local));
    }
    return box;
}

std::vector<Vec3> LensSolid::axial_outline(const Vec3& across, int steps) const {
    const double cx = dot(across, m_frame.u), cy = dot(across, m_frame.v);
    const double radius = 0.5 * m_p.diameter;
    std::vector<Vec3> outline;
    outline.reserve(2 * (steps + 1));
    const auto add = [&](double r, bool front) {
        const double x = r * cx, y = r * cy;
        const double z = front ? front_z(x, y) : back_z(x, y);
        outline.push_back(m_p.centre + m_frame.to_world({x, y, z}));
    };
    for (int i = 0; i <= steps; ++i) add(radius * (2.0 * i / steps - 1.0), true);
    for (int i = steps; i >= 0; --i) add(radius * (2.0 * i / steps - 1.0), false);
    return outline;
}

}  // namespace lenslab
