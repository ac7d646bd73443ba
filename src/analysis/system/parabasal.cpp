#include "analysis/system/parabasal.h"

#include <cmath>

#include "analysis/system/real_ray.h"
#include "util/scene_error.h"

namespace lenslab {

namespace {

// Steps in height (relative to the system's size) and in slope: central differences of
// rays this close are exact to about 1e-9, far below any first-order figure's use.
constexpr double kHeightStep = 1e-6;
constexpr double kSlopeStep = 1e-6;

// A unit vector across `d`, as near `towards` as it can be.
Vec3 across(const Vec3& d, const Vec3& towards) { return normalize(towards - d * dot(d, towards)); }

struct Transverse {
    double x, y, slope_x, slope_y;
};

}  // namespace

std::optional<ParabasalMatrices> parabasal_matrices(const OpticalSystem& system,
                                                    const Ray& reference, double nm) {
    const IndexRatios ratios = index_ratios(system, nm);
    const RealRay chief = trace_real_ray(system, reference, ratios, Rims::Ignore);
    if (chief.fate != RayFate::Passed) return std::nullopt;
    ParabasalMatrices m;
    m.reference = reference;
    m.exit_point = chief.exit_point();
    m.exit_direction = chief.direction;
    m.n_object = std::abs(system.n_before(0, nm));
    m.n_image = std::abs(system.n_after(system.surfaces.size() - 1, nm));
    const Vec3& d = reference.direction;
    const Vec3 y_in = across(d, {0, 1, 0});
    const Vec3 x_in = cross(y_in, d);
    const Vec3& e = m.exit_direction;
    const Vec3 y_out = across(e, {0, 1, 0});
    const Vec3 x_out = cross(y_out, e);

    // A ray's place and slopes on the plane across the exit ray at the exit point.
    const auto leave = [&](const Ray& ray) -> std::optional<Transverse> {
        const RealRay r = trace_real_ray(system, ray, ratios, Rims::Ignore);
        if (r.fate != RayFate::Passed) return std::nullopt;
        const double along = dot(r.direction, e);
        const Vec3 p =
            r.exit_point() + r.direction * (dot(m.exit_point - r.exit_point(), e) / along);
        const Vec3 off = p - m.exit_point;
        return Transverse{dot(off, x_out), dot(off, y_out), dot(r.direction, x_out) / along,
                          dot(r.direction, y_out) / along};
    };
    const double h = kHeightStep * system.scale();
    const auto moved = [&](const Vec3& side) { return Ray{reference.origin + side * h, d}; };
    const auto turned = [&](const Vec3& side) {
        return Ray{reference.origin, normalize(d + side * kSlopeStep)};
    };
    const auto up_h = leave(moved(y_in)), down_h = leave(moved(-y_in));
    const auto up_u = leave(turned(y_in)), down_u = leave(turned(-y_in));
    const auto right_h = leave(moved(x_in)), left_h = leave(moved(-x_in));
    const auto right_u = leave(turned(x_in)), left_u = leave(turned(-x_in));
    if (!up_h || !down_h || !up_u || !down_u || !right_h || !left_h || !right_u || !left_u)
        return std::nullopt;
    // (y, n u) in, (y', n' u') out: each column is the change of the outputs over a step.
    const double n = m.n_object, n2 = m.n_image;
    m.y.a = (up_h->y - down_h->y) / (2 * h);
    m.y.c = n2 * (up_h->slope_y - down_h->slope_y) / (2 * h);
    m.y.b = (up_u->y - down_u->y) / (2 * kSlopeStep * n);
    m.y.d = n2 * (up_u->slope_y - down_u->slope_y) / (2 * kSlopeStep * n);
    m.x.a = (right_h->x - left_h->x) / (2 * h);
    m.x.c = n2 * (right_h->slope_x - left_h->slope_x) / (2 * h);
    m.x.b = (right_u->x - left_u->x) / (2 * kSlopeStep * n);
    m.x.d = n2 * (right_u->slope_x - left_u->slope_x) / (2 * kSlopeStep * n);
    return m;
}

ParaxialResult parabasal_paraxial(const OpticalSystem& system, const ParabasalMatrices& m,
                                  double nm) {
    ParaxialResult r;
    r.wavelength_nm = nm;
    r.parabasal = true;
    r.a = m.y.a, r.b = m.y.b, r.c = m.y.c, r.d = m.y.d;
    r.power = -m.y.c;
    if (!(std::abs(r.power) * system.scale() > 1e-6)) {
        throw SceneError("objects",
                         "the lens system has no optical power in the y-z section about its "
                         "chief ray (afocal, or a cylinder lens whose power lies in x: turn it "
                         "a quarter about its axis to measure that section)");
    }
    r.efl = 1.0 / r.power;
    r.efl_x = m.x.c != 0 ? -1.0 / m.x.c : INFINITY;
    // As paraxial_trace's, measured along the reference ray from where it leaves the last
    // surface and where it starts.
    r.bfl = m.n_image * m.y.a / r.power;
    r.ffl = m.n_object * m.y.d / r.power;
    const Vec3 rear_focus = m.exit_point + m.exit_direction * r.bfl;
    const Vec3 front_focus = m.reference.origin - m.reference.direction * r.ffl;
    r.z_rear_focus = rear_focus.z;
    r.z_front_focus = front_focus.z;
    r.z_rear_principal = (rear_focus - m.exit_direction * (m.n_image / r.power)).z;
    r.z_front_principal = (front_focus + m.reference.direction * (m.n_object / r.power)).z;
    r.rear_focus = rear_focus;
    r.reference = m.reference;
    return r;
}

}  // namespace lenslab
