#include "scene/grin_ray.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace lenslab {

namespace {

// The state (r, T) and its derivative (T, n grad n).
struct GrinState {
    Vec3 r, T;
};

GrinState grin_derivative(const GrinMedium& m, const GrinState& y) {
    return {y.T, m.gradient(y.r) * m.index(y.r)};
}

GrinState grin_axpy(const GrinState& y, double h,
                    std::initializer_list<std::pair<double, const GrinState*>> terms) {
    GrinState out = y;
    for (const auto& term : terms) {
        out.r += term.second->r * (h * term.first);
        out.T += term.second->T * (h * term.first);
    }
    return out;
}

struct GrinStep {
    GrinState y;   // fifth-order solution
    GrinState k7;  // its derivative (the next step's first stage)
    double error;  // scaled error estimate: <= 1 is accepted
};

// One Dormand-Prince 5(4) step of size h from y, whose derivative is k1.
GrinStep grin_dopri_step(const GrinMedium& m, const GrinState& y, const GrinState& k1, double h,
                         double r_tolerance, double t_tolerance) {
    const GrinState k2 = grin_derivative(m, grin_axpy(y, h, {{1.0 / 5, &k1}}));
    const GrinState k3 = grin_derivative(m, grin_axpy(y, h, {{3.0 / 40, &k1}, {9.0 / 40, &k2}}));
    const GrinState k4 =
        grin_derivative(m, grin_axpy(y, h, {{44.0 / 45, &k1}, {-56.0 / 15, &k2}, {32.0 / 9, &k3}}));
    const GrinState k5 = grin_derivative(m, grin_axpy(y, h,
                                                      {{19372.0 / 6561, &k1},
                                                       {-25360.0 / 2187, &k2},
                                                       {64448.0 / 6561, &k3},
                                                       {-212.0 / 729, &k4}}));
    const GrinState k6 = grin_derivative(m, grin_axpy(y, h,
                                                      {{9017.0 / 3168, &k1},
                                                       {-355.0 / 33, &k2},
                                                       {46732.0 / 5247, &k3},
                                                       {49.0 / 176, &k4},
                                                       {-5103.0 / 18656, &k5}}));
    GrinStep s;
    s.y = grin_axpy(y, h,
                    {{35.0 / 384, &k1},
                     {500.0 / 1113, &k3},
                     {125.0 / 192, &k4},
                     {-2187.0 / 6784, &k5},
                     {11.0 / 84, &k6}});
    s.k7 = grin_derivative(m, s.y);
    // Fifth minus fourth order weights.
    const GrinState e = grin_axpy(GrinState{}, h,
                                  {{71.0 / 57600, &k1},
                                   {-71.0 / 16695, &k3},
                                   {71.0 / 1920, &k4},
                                   {-17253.0 / 339200, &k5},
                                   {22.0 / 525, &k6},
                                   {-1.0 / 40, &s.k7}});
    s.error = std::max(length(e.r) / r_tolerance, length(e.T) / t_tolerance);
    return s;
}

}  // namespace

GrinExit trace_grin_ray(const GrinMedium& medium, const Shape& shape, const Vec3& origin,
                        const Vec3& direction, const GrinRayOptions& options,
                        std::vector<Vec3>* path) {
    GrinExit out;
    const double size = std::max(shape.bounding_sphere().radius, 1e-300);
    const double r_tolerance = options.tolerance * size;
    const double t_tolerance = options.tolerance;
    // Steps shorter than this cannot be told from the surface: the ray has arrived.
    const double reach = r_tolerance;

    GrinState y{origin, direction * medium.index(origin)};
    GrinState k1 = grin_derivative(medium, y);
    double h = 0.1 * size / medium.index(origin);  // in t: a tenth of the solid's size
    double t_min = surface_epsilon(origin);        // leaving the entry point
    double travelled = 0;                          // geometric length of the accepted steps' chords
    if (path) path->assign(1, origin);

    // Every attempt counts, so a step shortened again and again at the surface cannot spin.
    for (int attempt = 0; attempt < 4 * options.max_steps && out.steps < options.max_steps;
         ++attempt) {
        const GrinStep s = grin_dopri_step(medium, y, k1, h, r_tolerance, t_tolerance);
        if (!(s.error <= 1.0)) {
            // A step a billionth of the solid's size still failing: no medium to follow.
            if (!(h * medium.index(y.r) > 1e-9 * size)) return out;
            ++out.rejected;
            h *= std::isfinite(s.error) ? std::max(0.2, 0.9 * std::pow(s.error, -0.2)) : 0.2;
            continue;
        }
        const Vec3 chord = s.y.r - y.r;
        const double chord_length = length(chord);
        SurfaceHit hit;
        // Looked for a little beyond the chord's end: a step ending within `reach` of the
        // surface, on either side, has arrived (rounding must not carry it out unseen).
        if (chord_length > 0 &&
            shape.intersect({y.r, chord / chord_length}, t_min, chord_length + reach, hit)) {
            const double fraction = hit.t / chord_length;
            if (std::abs(chord_length - hit.t) <= reach || hit.t <= reach) {
                // Ends on the surface: the chord's hit is the exit, exactly on the shape.
                ++out.steps;
                out.left = true;
                out.direction = normalize(s.y.T);
                out.hit = hit;
                out.hit.t = travelled + hit.t;
                if (path) path->push_back(hit.point);
                return out;
            }
            // Crossed the surface: shorten the step to end about where the chord did.
            h *= fraction;
            continue;
        }
        ++out.steps;
        travelled += chord_length;
        y = s.y;
        k1 = s.k7;
        t_min = 0.0;
        if (path) path->push_back(y.r);
        h *= std::min(5.0, 0.9 * std::pow(std::max(s.error, 1e-10), -0.2));
    }
    return out;
}

}  // namespace lenslab
