#pragma once
// The diffraction figures of `lenslab analyze --psf` and `--mtf` as JSON and as a table: the
// `psf` block (Strehl ratio, wavefront RMS, Airy radius, encircled energy there) and the
// `mtf` block (frequencies, the diffraction limit, and per field the tangential and sagittal
// curves).

#include <nlohmann/json.hpp>
#include <string>

#include "analysis/diffraction/diffraction_figures.h"

namespace lenslab {

nlohmann::ordered_json psf_json(const DiffractionFigures& figures);
nlohmann::ordered_json mtf_json(const DiffractionFigures& figures);

// The lines the table prints for each block asked for; lengths in the system's unit (mm).
std::string diffraction_table(const DiffractionFigures& figures, bool psf, bool mtf);

}  // namespace lenslab
