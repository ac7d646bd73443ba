#include "analysis/system/ray_aiming.h"

#include <cmath>

#include "analysis/aberrations/aberrations.h"

namespace lenslab {

namespace {

constexpr int kAimIterations = 30;
constexpr double kAimTolerance = 1e-11;  // of the system's size, at the stop
constexpr double kAimStep = 1e-7;        // finite-difference step (relative)

}  // namespace

RayAimer::RayAimer(const OpticalSystem& system, const FirstOrder& first_order, double field,
                   double wavelength_nm, double field_x)
    : system_(system),
      first_order_(first_order),
      field_(field),
      field_x_(field_x),
      ratios_(index_ratios(system, wavelength_nm)),
      scale_(system.scale()) {
    if (!first_order.object_distance) {
        z_start_ = beam_start_z(system);
        if (field_x == 0.0) {  // in the meridional plane, as it always was: bit for bit
            const double angle = field * M_PI / 180.0;
            direction_y_ = std::sin(angle);
            direction_z_ = std::cos(angle);
        } else {
            const Vec3 d = normalize(
                Vec3{std::tan(field_x * M_PI / 180.0), std::tan(field * M_PI / 180.0), 1.0});
            direction_x_ = d.x;
            direction_y_ = d.y;
            direction_z_ = d.z;
        }
    }
}

Ray RayAimer::candidate(double a, double b) const {
    if (first_order_.object_distance) {
        return Ray{Vec3{field_x_, field_, -*first_order_.object_distance},
                   normalize(Vec3{a, b, 1.0})};
    }
    return Ray{Vec3{a, b, z_start_}, Vec3{direction_x_, direction_y_, direction_z_}};
}

std::optional<Vec3> RayAimer::at_stop(double a, double b) const {
    const RealRay ray = trace_real_ray(system_, candidate(a, b), ratios_, Rims::Ignore);
    const int stop = first_order_.stop;
    if (ray.fate != RayFate::Passed && ray.surface <= stop) return std::nullopt;
    // A decentred or tilted stop is aimed at in its own frame (about its vertex).
    const SystemSurface& s = system_.surfaces[stop];
    const Vec3& p = ray.points[stop + 1];
    return s.pose ? s.pose->axes.to_local(p - s.pose->vertex) : p;
}

std::optional<RealRay> RayAimer::trace(double px, double py) const {
    const auto start = aim(px, py);
    if (!start) return std::nullopt;
    return trace_real_ray(system_, *start, ratios_);
}

std::optional<Ray> RayAimer::aim(double px, double py) const {
    const FirstOrder& f = first_order_;
    const double r_stop = f.stop_semi_diameter;
    const double tx = px * r_stop, ty = py * r_stop;
    // The paraxial aim: through (px, py) scaled to the entrance pupil.
    const double z_ep = f.entrance_pupil.position, r_ep = 0.5 * f.entrance_pupil.diameter;
    double a, b, step;
    if (f.object_distance) {
        const double reach = z_ep + *f.object_distance;
        a = (px * r_ep - field_x_) / reach;
        b = (py * r_ep - field_) / reach;
        step = kAimStep;
    } else {
        a = px * r_ep + direction_x_ / direction_z_ * (z_start_ - z_ep);
        b = py * r_ep + direction_y_ / direction_z_ * (z_start_ - z_ep);
        step = kAimStep * scale_;
    }
    if (f.ray_aiming == RayAiming::Paraxial) return candidate(a, b);
    const double tolerance = kAimTolerance * scale_;
    for (int i = 0; i < kAimIterations; ++i) {
        const auto p = at_stop(a, b);
        if (!p) return std::nullopt;
        const double ex = p->x - tx, ey = p->y - ty;
        if (std::hypot(ex, ey) < tolerance) return candidate(a, b);
        const auto pa = at_stop(a + step, b), pb = at_stop(a, b + step);
        if (!pa || !pb) return std::nullopt;
        // Jacobian of the stop point against the aim, and the Newton step it gives.
        const double j11 = (pa->x - p->x) / step, j12 = (pb->x - p->x) / step;
        const double j21 = (pa->y - p->y) / step, j22 = (pb->y - p->y) / step;
        const double det = j11 * j22 - j12 * j21;
        if (!(std::abs(det) > 0)) return std::nullopt;
        a -= (j22 * ex - j12 * ey) / det;
        b -= (j11 * ey - j21 * ex) / det;
    }
    return std::nullopt;
}

}  // namespace lenslab
