#pragma once
// `lenslab analyze --wavefront` as JSON (the `wavefront` block: per field and wavelength the
// RMS, peak-to-valley, Strehl ratio, Zernike coefficients and the OPD map) and as a table.

#include <nlohmann/json.hpp>
#include <string>

#include "analysis/diffraction/wavefront_figures.h"

namespace lenslab {

nlohmann::ordered_json wavefront_json(const WavefrontFigures& figures);

std::string wavefront_table(const WavefrontFigures& figures);

}  // namespace lenslab
