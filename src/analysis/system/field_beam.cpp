#include "analysis/system/field_beam.h"

#include "analysis/system/ray_aiming.h"

namespace lenslab {

std::optional<ExitRay> passed_exit_ray(const OpticalSystem& system,
                                       const std::optional<RealRay>& ray) {
    if (!ray || ray->fate != RayFate::Passed || !(ray->direction.z * system.image_travel() > 0))
        return std::nullopt;
    return ExitRay{ray->exit_point(), ray->direction};
}

FieldBeam trace_field_beam(const OpticalSystem& system, const FirstOrder& first_order, double field,
                           double nm, int rings, double field_x) {
    FieldBeam beam;
    beam.field = field;
    beam.wavelength_nm = nm;
    const RayAimer aimer(system, first_order, field, nm, field_x);
    bool centre = true;  // the hexapolar grid starts at the stop's centre
    for (const PupilPoint& q : hexapolar_pupil(rings)) {
        if (const auto ray = passed_exit_ray(system, aimer.trace(q.x, q.y))) {
            beam.rays.push_back(*ray);
            if (centre) beam.chief = beam.rays.back();
        } else {
            ++beam.lost;
        }
        centre = false;
    }
    return beam;
}

}  // namespace lenslab
