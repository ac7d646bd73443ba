#pragma once
// Reading the spectral parts of a scene: refractive index models and catalogue glasses,
// and light spectra.

#include <nlohmann/json.hpp>

#include "optics/glass.h"
#include "optics/spectrum.h"
#include "scene/json_reader.h"

namespace lenslab {

// `ior`: a number, or {"model": "cauchy", "A", "B", "C"} | {"model": "sellmeier", "B": [..],
// "C": [..]} | {"model": "abbe", "n_d", "V_d"}.
IndexModelPtr read_index_model(const nlohmann::json& j, const std::string& path);
// `glass`: a catalogue name (error lists the catalogue).
const Glass& read_glass(const nlohmann::json& j, const std::string& path);
// `spectrum`: "d65" | {"blackbody": kelvin} | {"line": nm, "width": nm}. Normalised to the
// radiant power of D65 white.
SpectrumPtr read_spectrum(const nlohmann::json& j, const std::string& path);
// The light's spectral power: its `spectrum` if given (then `color` must not be), else its
// colour as D65-based illuminant; times `power`.
SpectrumPtr light_spectrum(JsonObjectReader& r, Rgb& color, double power);
// A laser's: its `spectrum` if given (then `wavelength` must not be), else a line at
// `wavelength_nm` (its `wavelength`, read and checked by the caller), 0.1 nm wide.
SpectrumPtr laser_spectrum(JsonObjectReader& r, double wavelength_nm, double power);

}  // namespace lenslab
