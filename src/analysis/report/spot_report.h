#pragma once
// The spot diagrams of `lenslab analyze --spots` (spot_diagrams.h) as JSON and as a table.

#include <nlohmann/json.hpp>
#include <string>

#include "analysis/aberrations/spot_diagrams.h"

namespace lenslab {

// {image_z, image_position, rings, rays_per_beam, reference, wavelengths_nm, weights,
//  working_f_number, per_wavelength: [...], polychromatic: [...]} (docs/optical-bench.md).
nlohmann::ordered_json spots_json(const OpticalSystem& system, const SpotDiagrams& spots);
std::string spots_table(const OpticalSystem& system, const SpotDiagrams& spots);

}  // namespace lenslab
