#pragma once
// The diffraction figures of `lenslab analyze --psf` and `--mtf` as JSON and as a table: the
// `psf` block (on the axis at best focus: Strehl ratio, wavefront RMS, Airy radius, encircled
// energy there; per field the polychromatic PSF, field_psf.h) and the
// `mtf` block (frequencies, the polychromatic diffraction limit, and per field the
// polychromatic tangential and sagittal curves, field_mtf.h).

#include <nlohmann/json.hpp>
#include <string>

#include "analysis/diffraction/diffraction_figures.h"
#include "analysis/diffraction/field_mtf.h"
#include "analysis/diffraction/field_psf.h"

namespace lenslab {

nlohmann::ordered_json psf_json(const DiffractionFigures& figures,
                                const std::vector<FieldPsf>& fields);
nlohmann::ordered_json mtf_json(const DiffractionFigures& figures, const FieldMtfs& mtf);
nlohmann::ordered_json through_focus_json(const ThroughFocusMtf& t);
std::string through_focus_table(const ThroughFocusMtf& t);

// The lines the table prints for each block asked for (psfs, mtf: none when not asked for);
// lengths in the system's unit (mm).
std::string diffraction_table(const DiffractionFigures& figures, const std::vector<FieldPsf>* psfs,
                              const FieldMtfs* mtf);

}  // namespace lenslab
