#pragma once
// The ray fans of `lenslab analyze --fans` (ray_fans.h) as JSON and as a table.

#include <nlohmann/json.hpp>
#include <string>

#include "analysis/aberrations/ray_fans.h"

namespace lenslab {

// {image_z, image_position, reference, reference_wavelength_nm, pupil,
//  fields: [{field, chief: {x, y}, fans: [{wavelength, tangential, sagittal}]}]}
// (docs/optical-bench.md); a vignetted ray's error is null.
nlohmann::ordered_json fans_json(const OpticalSystem& system, const RayFans& fans);
std::string fans_table(const OpticalSystem& system, const RayFans& fans);

}  // namespace lenslab
