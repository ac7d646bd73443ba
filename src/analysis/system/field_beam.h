#pragma once
// The beam from one field point at one wavelength, aimed (ray_aiming.h) through the
// hexapolar grid of the aperture stop (aberrations.h): what the spot diagrams, the
// polychromatic RMS spot of the optimiser and the field figures are made of.

#include <optional>
#include <vector>

#include "analysis/aberrations/aberrations.h"
#include "analysis/system/first_order.h"
#include "analysis/system/real_ray.h"

namespace lenslab {

struct FieldBeam {
    double field = 0, wavelength_nm = 0;
    std::vector<ExitRay> rays;     // the rays that passed every surface, grid order
    int lost = 0;                  // vignetted, totally reflected or not aimable
    std::optional<ExitRay> chief;  // the ray through the stop's centre, when it passed
};

// The ray as it leaves the last surface, when it passed every surface going forward.
std::optional<ExitRay> passed_exit_ray(const OpticalSystem& system,
                                       const std::optional<RealRay>& ray);

// `field` in y, `field_x` in x (ray_aiming.h).
FieldBeam trace_field_beam(const OpticalSystem& system, const FirstOrder& first_order, double field,
                           double wavelength_nm, int rings, double field_x = 0.0);

}  // namespace lenslab
