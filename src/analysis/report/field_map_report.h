#pragma once
// The field map of `lenslab analyze --field-map N` (field_map.h) as JSON and as a table.

#include <nlohmann/json.hpp>
#include <string>

#include "analysis/aberrations/field_map.h"

namespace lenslab {

// {wavelength_nm, image_z, image_position, rings, fields_x, fields_y, rms: [[...], ...]}:
// rms[j][i] at fields_x[i], fields_y[j], null where no ray passed (docs/optical-bench.md).
nlohmann::ordered_json field_map_json(const OpticalSystem& system, const FieldMap& map);
std::string field_map_table(const OpticalSystem& system, const FieldMap& map);

}  // namespace lenslab
