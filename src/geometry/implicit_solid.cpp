#include "geometry/implicit_solid.h"

#include <cmath>
#include <sstream>
#include <utility>

#include "math/bracketed_newton.h"

namespace lenslab {

namespace {

const std::vector<std::string> kImplicitVariables{"x", "y", "z"};
constexpr const char* kImplicitHint = "(use x, y and z)";

// Load-time sampling: a grid of this many points per axis inside the box.
constexpr int kCheckGrid = 33;

bool inside(double v) { return v <= 0.0; }  // NaN counts as outside

}  // namespace

ImplicitSolid::ImplicitSolid(const std::string& formula, const Aabb& box, int steps,
                             const Vec3& centre, std::string owner)
    : m_formula(std::make_shared<Formula>(formula, kImplicitVariables, kImplicitHint)),
      m_box(box),
      m_steps(std::max(1, steps)),
      m_centre(centre),
      m_diagonal(length(box.extent())),
      m_owner(std::move(owner)) {}

double ImplicitSolid::defined_f(Formula::Evaluator& f, const Vec3& p) const {
    const double v = f({p.x, p.y, p.z, 0.0});
    if (std::isnan(v)) {
        std::ostringstream point;
        point.precision(10);
        point << "(x, y, z) = (" << p.x << ", " << p.y << ", " << p.z << ")";
        throw UndefinedFormulaError(m_owner, *m_formula, point.str(), {p.x, p.y, p.z, 0.0});
    }
    return v;
}

std::optional<std::string> ImplicitSolid::check(const std::string& text) {
    try {
        Formula f(text, kImplicitVariables, kImplicitHint);
    } catch (const FormulaError& e) {
        return e.message();
    }
    return std::nullopt;
}

std::optional<std::string> ImplicitSolid::check_values() const {
    Formula::Evaluator& f = m_formula->local();
    bool any_inside = false;
    std::optional<std::string> undefined;
    for_each_grid_point(m_box, kCheckGrid, [&](const Vec3& p) {
        const double v = f({p.x, p.y, p.z, 0.0});
        if (std::isnan(v)) {
            std::ostringstream msg;
            msg.precision(10);
            const std::string why = m_formula->why_not_finite({p.x, p.y, p.z, 0.0});
            msg << "f undefined at (x, y, z) = (" << p.x << ", " << p.y << ", " << p.z
                << ") inside the bounds" << (why.empty() ? "" : " (" + why + ")");
            undefined = msg.str();
            return false;
        }
        any_inside = any_inside || inside(v);
        return true;
    });
    if (undefined) return undefined;
    if (!any_inside) {
        return "f > 0 at every point sampled inside the bounds, so the solid is empty (the "
               "inside is where f <= 0)";
    }
    return std::nullopt;
}

bool ImplicitSolid::contains(const Vec3& world) const {
    const Vec3 p = world - m_centre;
    for (int a = 0; a < 3; ++a) {
        if (p[a] < m_box.lo[a] || p[a] > m_box.hi[a]) return false;
    }
    return inside(defined_f(m_formula->local(), p));
}

bool ImplicitSolid::intersect(const Ray& world_ray, double t_min, double t_max,
                              SurfaceHit& hit) const {
    // Everything below is relative to the centre; only the hit point goes back.
    const Ray ray{world_ray.origin - m_centre, world_ray.direction};
    const Vec3& o = ray.origin;
    const Vec3& d = ray.direction;
    // The box's slabs (Kay & Kajiya), remembering which face the ray enters and leaves by.
    double box_in = -INFINITY, box_out = INFINITY;
    int axis_in = -1, axis_out = -1;
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0.0) {
            if (o[a] < m_box.lo[a] || o[a] > m_box.hi[a]) return false;
            continue;
        }
        double t0 = (m_box.lo[a] - o[a]) / d[a], t1 = (m_box.hi[a] - o[a]) / d[a];
        if (t0 > t1) std::swap(t0, t1);
        if (t0 > box_in) {
            box_in = t0;
            axis_in = a;
        }
        if (t1 < box_out) {
            box_out = t1;
            axis_out = a;
        }
    }
    if (!(box_in < box_out)) return false;
    auto face_normal = [&](int axis, double sign) {
        Vec3 n;
        n[axis] = std::copysign(1.0, sign);
        return n;
    };

    Formula::Evaluator& f = m_formula->local();
    // Inside the box, where the march samples, f must be a number; the slope's probes may
    // step just outside it.
    auto phi = [&](double t) {
        const Vec3 p = ray.at(t);
        return f({p.x, p.y, p.z, 0.0});
    };
    auto defined_phi = [&](double t) { return defined_f(f, ray.at(t)); };

    // Entering the box where the solid fills it: the box face is the solid's surface.
    if (in_range(box_in, t_min, t_max) && axis_in >= 0 && inside(defined_phi(box_in))) {
        hit = {box_in, world_ray.at(box_in), face_normal(axis_in, -d[axis_in])};
        return true;
    }
    const double lo = std::max(t_min, box_in), hi = std::min(t_max, box_out);
    if (!(lo < hi)) return false;

    const double speed = length(d);
    const double step = m_diagonal / m_steps / speed;
    const double h = 6e-6 * m_diagonal;  // central-difference step (Numerical Recipes 5.7)
    const double ht = h / speed;
    auto phi_and_slope = [&](double t) {
        return ValueAndSlope{phi(t), (phi(t + ht) - phi(t - ht)) / (2.0 * ht)};
    };
    const double tolerance = 1e-12 * (m_diagonal + std::abs(lo)) / speed;

    double t0 = lo, f0 = defined_phi(lo);
    while (t0 < hi) {
        const double t1 = std::min(hi, t0 + step);
        if (!(t1 > t0)) break;
        const double f1 = defined_phi(t1);
        if (inside(f0) != inside(f1) && !std::isnan(f0) && !std::isnan(f1)) {
            const auto root = bracketed_newton(phi_and_slope, t0, t1, f0, f1, tolerance);
            if (root && in_range(*root, t_min, t_max)) {
                const Vec3 p = ray.at(*root);
                Vec3 g{f({p.x + h, p.y, p.z, 0}) - f({p.x - h, p.y, p.z, 0}),
                       f({p.x, p.y + h, p.z, 0}) - f({p.x, p.y - h, p.z, 0}),
                       f({p.x, p.y, p.z + h, 0}) - f({p.x, p.y, p.z - h, 0})};
                const bool entering = !inside(f0);
                // The crossing decides the side: the normal must face the ray on the way
                // in and away from it on the way out. A gradient that is zero or not finite
                // (a cusp, a crease) or that disagrees (rounding in a graze) yields to it.
                if (!is_finite(g) || !(length(g) > 0.0)) {
                    g = entering ? -d : d;
                } else if ((dot(g, d) < 0.0) != entering) {
                    g = g - d * (2.0 * dot(g, d) / dot(d, d));
                }
                hit = {*root, world_ray.at(*root), normalize(g)};
                return true;
            }
        }
        t0 = t1;
        f0 = f1;
    }
    // Leaving the box while inside the solid: the box face is the way out.
    if (in_range(box_out, t_min, t_max) && inside(f0) && axis_out >= 0) {
        hit = {box_out, world_ray.at(box_out), face_normal(axis_out, d[axis_out])};
        return true;
    }
    return false;
}

}  // namespace lenslab
