#include "analysis/system/real_chief_ray.h"

#include "analysis/system/ray_aiming.h"

namespace lenslab {

std::optional<RealChiefRay> trace_real_chief_ray(const OpticalSystem& system, const FirstOrder& f) {
    RealChiefRay result;
    if (f.field == 0.0) return result;
    const auto ray = RayAimer(system, f, f.field, f.wavelength_nm).trace(0.0, 0.0);
    if (!ray || ray->fate != RayFate::Passed) return std::nullopt;
    const double z_image = system.last_vertex() + f.image_position;
    result.image_height = at_plane(ray->exit_point(), ray->direction, z_image).y;
    if (f.parabasal) {
        // Decentred or tilted: heights from where the central field's chief ray lands.
        const RealRay centre = trace_real_ray(system, f.parabasal->reference, f.wavelength_nm);
        if (centre.fate != RayFate::Passed) return std::nullopt;
        result.image_height -= at_plane(centre.exit_point(), centre.direction, z_image).y;
    }
    result.distortion = (result.image_height - f.image_height) / f.image_height;
    return result;
}

}  // namespace lenslab
