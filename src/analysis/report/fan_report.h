#pragma once
// The ray fans of `lenslab analyze --fans` (ray_fans.h) as JSON and as a table.

#include <nlohmann/json.hpp>
#include <string>

#include "analysis/aberrations/ray_fans.h"

namespace lenslab {

// {image_z, image_position, reference, reference_wavelength_nm, pupil,
//  fields: [{field, chief: {x, y}, fans: [{wavelength, tangential, sagittal}]}]}
// (docs/optical-bench.md); a vignetted ray's error is null.
// OPD fans (opd_fans.h) have the same layout, in waves, with "unit": "waves" and their
// reference ("each wavelength's chief ray and reference sphere").
nlohmann::ordered_json fans_json(const OpticalSystem& system, const RayFans& fans,
                                 FanQuantity quantity = FanQuantity::TransverseError);
std::string fans_table(const OpticalSystem& system, const RayFans& fans,
                       FanQuantity quantity = FanQuantity::TransverseError);

}  // namespace lenslab
