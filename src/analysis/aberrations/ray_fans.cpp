#include "analysis/aberrations/ray_fans.h"

#include <cmath>

#include "analysis/system/field_beam.h"
#include "analysis/system/ray_aiming.h"

namespace lenslab {

namespace {

// Where the ray through stop point (px, py) crosses the plane z, if it passes every surface.
std::optional<Vec3> fan_hit(const OpticalSystem& system, const RayAimer& aimer, double px,
                            double py, double z) {
    const auto ray = passed_exit_ray(system, aimer.trace(px, py));
    if (!ray) return std::nullopt;
    return at_plane(ray->point, ray->direction, z);
}

}  // namespace

RayFans ray_fans(const OpticalSystem& system, const FirstOrder& first_order,
                 const RayFanOptions& options) {
    RayFans r;
    r.image_z = options.image_z.value_or(system.last_vertex() + first_order.image_position);
    r.primary_nm = first_order.wavelength_nm;
    const int n = std::max(options.points, 2);
    for (int i = 0; i < n; ++i) r.pupil.push_back(-1.0 + 2.0 * i / (n - 1));
    const std::vector<double> wavelengths = options.wavelengths.empty()
                                                ? std::vector<double>{first_order.wavelength_nm}
                                                : options.wavelengths;
    for (double field : options.fields) {
        FieldFans f;
        f.field = field;
        f.reference = fan_hit(system, RayAimer(system, first_order, field, r.primary_nm), 0.0, 0.0,
                              r.image_z);
        for (double nm : wavelengths) {
            const RayAimer aimer(system, first_order, field, nm);
            RayFan fan;
            fan.wavelength_nm = nm;
            for (double p : r.pupil) {
                const auto t = fan_hit(system, aimer, 0.0, p, r.image_z);
                const auto s = fan_hit(system, aimer, p, 0.0, r.image_z);
                fan.tangential.push_back(t && f.reference ? t->y - f.reference->y : NAN);
                fan.sagittal.push_back(s && f.reference ? s->x - f.reference->x : NAN);
            }
            f.fans.push_back(std::move(fan));
        }
        r.fields.push_back(std::move(f));
    }
    return r;
}

}  // namespace lenslab
