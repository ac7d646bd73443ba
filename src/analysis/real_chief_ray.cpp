#include "analysis/real_chief_ray.h"

#include <cmath>

#include "analysis/aberrations.h"
#include "analysis/real_ray.h"

namespace lenslab {

namespace {

constexpr int kAimIterations = 40;

// The ray leaving the field point with aim parameter p: for an object at infinity the
// height at which the collimated ray (at the field angle) crosses z = z_start; for a finite
// object the slope of the ray from the object point.
Ray chief_candidate(const OpticalSystem& system, const FirstOrder& f, double p) {
    if (f.object_distance) {
        return Ray{Vec3{0.0, f.field, -*f.object_distance}, normalize(Vec3{0.0, p, 1.0})};
    }
    const double angle = f.field * M_PI / 180.0;
    return Ray{Vec3{0.0, p, beam_start_z(system)}, Vec3{0.0, std::sin(angle), std::cos(angle)}};
}

}  // namespace

std::optional<RealChiefRay> trace_real_chief_ray(const OpticalSystem& system, const FirstOrder& f) {
    RealChiefRay result;
    if (f.field == 0.0) return result;
    const double nm = f.wavelength_nm;
    const double scale = std::max(system.last_vertex(), 2.0 * system.max_semi_diameter());
    // Height at the stop of the ray with aim p; NaN when it does not get there.
    const auto miss = [&](double p, RealRay* out) -> double {
        const RealRay ray = trace_real_ray(system, chief_candidate(system, f, p), nm);
        if (out) *out = ray;
        if (ray.fate != RayFate::Passed && ray.surface <= f.stop) return NAN;
        return ray.points[f.stop + 1].y;
    };
    // The paraxial chief ray's aim, and a second guess nearby.
    double p0 = f.object_distance ? f.chief.u0 : f.chief.height_before(beam_start_z(system));
    double p1 = p0 + (f.object_distance ? 1e-3 : 1e-3 * scale);
    double m0 = miss(p0, nullptr), m1 = miss(p1, nullptr);
    for (int i = 0; i < kAimIterations && std::isfinite(m0) && std::isfinite(m1); ++i) {
        if (std::abs(m1) < 1e-13 * scale || m1 == m0) break;
        const double p2 = p1 - m1 * (p1 - p0) / (m1 - m0);
        p0 = p1, m0 = m1;
        p1 = p2, m1 = miss(p1, nullptr);
    }
    if (!std::isfinite(m1) || std::abs(m1) > 1e-9 * scale) return std::nullopt;
    RealRay ray;
    miss(p1, &ray);
    if (ray.fate != RayFate::Passed) return std::nullopt;
    const double z_image = system.last_vertex() + f.image_position;
    result.image_height = at_plane(ray.exit_point(), ray.direction, z_image).y;
    result.distortion = (result.image_height - f.image_height) / f.image_height;
    return result;
}

}  // namespace lenslab
