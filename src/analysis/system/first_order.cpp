#include "analysis/system/first_order.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "analysis/system/parabasal.h"
#include "analysis/system/ray_aiming.h"
#include "util/scene_error.h"

namespace lenslab {

namespace {

// A pupil this far away (relative to the system's size) counts as at infinity.
constexpr double kTelecentricRatio = 1e12;

double system_scale(const OpticalSystem& system) { return system.scale(); }

// The axial point where a ray of this height and slope crosses the axis, relative to the
// plane where it has that height; infinity when it runs parallel to the axis.
double axis_crossing(double y, double u, double scale) {
    if (std::abs(y) > kTelecentricRatio * scale * std::abs(u)) {
        return (y > 0) == (u > 0) ? -INFINITY : INFINITY;
    }
    return -y / u;
}

double largest_field(const std::vector<double>& fields) {
    double field = 0.0;
    for (double f : fields) {
        if (std::abs(f) > std::abs(field)) field = f;
    }
    return field;
}

// The parabasal matrices about the chief ray of the central field, aimed through the centre
// of the real stop from the pupils as designed (f: stop, entrance pupil position, object).
ParabasalMatrices central_parabasal(const OpticalSystem& system, FirstOrder f) {
    f.ray_aiming = RayAiming::Real;
    const double field = 0.0;
    const std::optional<Ray> chief = RayAimer(system, f, field, f.wavelength_nm).aim(0, 0);
    std::optional<ParabasalMatrices> m;
    if (chief) m = parabasal_matrices(system, *chief, f.wavelength_nm);
    if (!m) {
        throw SceneError("objects",
                         "the chief ray of the central field does not pass the decentred or "
                         "tilted system (or a ray beside it does not), so it has no parabasal "
                         "first-order data");
    }
    return *m;
}

}  // namespace

FirstOrder first_order(const OpticalSystem& system, const ParaxialResult& paraxial,
                       const FirstOrderOptions& o) {
    const int count = static_cast<int>(system.surfaces.size());
    if (o.stop < 0 || o.stop >= count) {
        throw SceneError("--stop", "surface " + std::to_string(o.stop + 1) +
                                       " is not in the system (surfaces 1 to " +
                                       std::to_string(count) + ")");
    }
    const double nm = o.wavelength_nm;
    const double scale = system_scale(system);
    FirstOrder f;
    f.wavelength_nm = nm;
    f.stop = o.stop;
    f.ray_aiming = o.ray_aiming;
    f.efl = paraxial.efl;
    f.bfl = paraxial.bfl;

    // Two independent rays from the plane z = 0; every paraxial ray is a sum of them.
    const ParaxialRay height_ray = trace_paraxial_ray(system, nm, 1.0, 0.0);
    const ParaxialRay slope_ray = trace_paraxial_ray(system, nm, 0.0, 1.0);
    const double a = height_ray.surfaces[o.stop].y;  // y at the stop = a y0 + b u0
    const double b = slope_ray.surfaces[o.stop].y;
    // Rays through the centre of the stop have a y0 + b u0 = 0: in object space they all
    // cross the axis at z = b / a, the entrance pupil; a point at height r there maps to
    // height a r on the stop.
    if (std::abs(b) > kTelecentricRatio * scale * std::abs(a)) {
        throw SceneError("--stop", "the entrance pupil of stop surface " +
                                       std::to_string(o.stop + 1) +
                                       " lies at infinity (telecentric in object space)");
    }
    f.entrance_pupil.position = b / a;
    const double z_ep = f.entrance_pupil.position;
    f.object_distance = o.object_distance;
    std::optional<ParabasalMatrices> parabasal;
    if (!system.coaxial()) {
        parabasal = central_parabasal(system, f);
        f.parabasal = parabasal_paraxial(system, *parabasal, nm);
        f.efl = f.parabasal->efl;
        f.bfl = f.parabasal->bfl;
    }
    if (o.epd > 0) {
        f.entrance_pupil.diameter = o.epd;
    } else if (o.f_number > 0) {
        f.entrance_pupil.diameter = std::abs(f.efl) / o.f_number;
    } else {
        f.entrance_pupil.diameter = 2.0 * system.surfaces[o.stop].semi_diameter / std::abs(a);
    }
    const double r_ep = 0.5 * f.entrance_pupil.diameter;
    f.stop_semi_diameter = std::abs(a) * r_ep;

    // The unit chief ray: slope 1 in object space, through the centre of the entrance pupil.
    const ParaxialRay unit_chief = combine_rays(-z_ep, height_ray, 1.0, slope_ray);
    f.field = largest_field(o.fields);
    if (o.object_distance) {
        const double d = *o.object_distance;
        if (!(std::abs(d + z_ep) > 1e-12 * scale)) {
            throw SceneError("--object-distance",
                             "the object lies on the entrance pupil: no ray from its axial "
                             "point fills the stop");
        }
        const double u0 = r_ep / (d + z_ep);
        f.marginal = combine_rays(u0 * d, height_ray, u0, slope_ray);
        f.chief = combine_rays(-f.field / (d + z_ep), unit_chief, 0.0, unit_chief);
    } else {
        f.marginal = combine_rays(r_ep, height_ray, 0.0, slope_ray);
        f.chief = combine_rays(std::tan(f.field * M_PI / 180.0), unit_chief, 0.0, unit_chief);
    }

    const ParaxialRaySurface& m = f.marginal.last();
    const ParaxialRaySurface& c = unit_chief.last();
    f.image_position = axis_crossing(m.y, m.u_after, scale);
    f.image_height = f.chief.height_after(system, system.last_vertex() + f.image_position);
    f.exit_pupil.position = axis_crossing(c.y, c.u_after, scale);
    f.exit_pupil.diameter = std::isfinite(f.exit_pupil.position)
                                ? 2.0 * std::abs(f.marginal.height_after(
                                            system, system.last_vertex() + f.exit_pupil.position))
                                : INFINITY;
    f.f_number = std::abs(f.efl) / f.entrance_pupil.diameter;
    f.na = std::abs(m.n_after * m.u_after);
    f.working_f_number = 1.0 / (2.0 * f.na);
    const double n0 = system.n_before(0, nm);
    f.lagrange_invariant = n0 * (f.chief.u0 * f.marginal.y0 - f.marginal.u0 * f.chief.y0);
    if (o.object_distance) f.magnification = n0 * f.marginal.u0 / (m.n_after * m.u_after);
    if (parabasal) {
        // Read off the y-z section about the central chief ray: a ray of height h (or, from
        // a near object, of slope u) leaves at y' = A h (B n u), n' u' = C h (D n u).
        const ParabasalMatrices::Section& s = parabasal->y;
        Vec3 image = f.parabasal->rear_focus;
        if (o.object_distance) {
            image = parabasal->exit_point +
                    parabasal->exit_direction * (-parabasal->n_image * s.b / s.d);
            f.na = std::abs(s.d * n0 * f.marginal.u0);
            f.magnification = (s.a * s.d - s.b * s.c) / s.d;
            f.image_height = *f.magnification * f.field;
        } else {
            f.na = std::abs(s.c * r_ep);
            f.image_height = f.efl * std::tan(f.field * M_PI / 180.0);
        }
        f.image_position = image.z - system.last_vertex();
        f.working_f_number = 1.0 / (2.0 * f.na);
    }
    return f;
}

const char* ray_aiming_name(RayAiming aiming) {
    return aiming == RayAiming::Paraxial ? "paraxial" : "real";
}

std::optional<RayAiming> ray_aiming_named(const std::string& name) {
    for (RayAiming a : {RayAiming::Real, RayAiming::Paraxial}) {
        if (name == ray_aiming_name(a)) return a;
    }
    return std::nullopt;
}

}  // namespace lenslab
