#pragma once
// The field curves (field_curves.h) and the chromatic focal shift (focal_shift.h) of
// `lenslab analyze --field-curves` and `--focal-shift` as JSON and as tables.

#include <nlohmann/json.hpp>
#include <string>

#include "analysis/aberrations/field_curves.h"
#include "analysis/aberrations/focal_shift.h"

namespace lenslab {

// {image_z, image_position, differential_pupil, curves: [{wavelength, fields, tangential,
//  sagittal, chief_height, paraxial_height, distortion}]}, NaN as null.
nlohmann::ordered_json field_curves_json(const OpticalSystem& system, const FieldCurves& curves);
std::string field_curves_table(const OpticalSystem& system, const FieldCurves& curves);

// {reference_wavelength_nm, wavelengths, shift}.
nlohmann::ordered_json focal_shift_json(const FocalShift& shift);
std::string focal_shift_table(const FocalShift& shift);

}  // namespace lenslab
