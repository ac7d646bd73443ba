#pragma once
// The refractive index of standard air, which ties lenslab's index convention together: glass
// catalogues give indices relative to air at 20 degC and 1 atm, with wavelengths in air, and
// data measured against vacuum (water, fused silica) is converted with this model.

#include "optics/glass.h"

namespace lenslab {

// Dry air (400 ppm CO2) at 20 degC and 101 325 Pa, by the updated Edlen equation of Birch and
// Downs (Metrologia 30, 155 (1993); correction Metrologia 31, 315 (1994)), at a wavelength in
// air in nm. 1.000 272 at the d line.
double standard_air_index(double air_nm);

// The vacuum wavelength of light whose wavelength in standard air is `air_nm`.
double vacuum_wavelength(double air_nm);

// An index measured against vacuum at vacuum wavelengths, re-expressed as catalogues do:
// n_rel(lambda_air) = n_abs(lambda_vac) / n_air with lambda_vac = n_air * lambda_air.
std::shared_ptr<IndexModel> relative_to_air(IndexModelPtr absolute);

// The other way: a catalogue's (air-relative) index as an absolute one at vacuum wavelengths,
// n_abs(lambda_vac) = n_rel(lambda_air) * n_air with lambda_air = lambda_vac / n_air.
std::shared_ptr<IndexModel> relative_to_vacuum(IndexModelPtr relative_to_air);

}  // namespace lenslab
