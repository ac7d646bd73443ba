#pragma once
// The false-colour figures of the diffraction block (map_figure.h): the polychromatic PSF of
// every field (`lenslab analyze --psf-png`) and the OPD map of every field at the primary
// wavelength (`--opd-png`), +y up in both.

#include <string>
#include <vector>

#include "analysis/diffraction/field_psf.h"
#include "analysis/diffraction/wavefront_figures.h"
#include "image/false_colour.h"

namespace lenslab {

// `unit`: the system's length unit for the panels' widths ("mm"); `field_unit` follows each
// field's number ("deg" for angles).
Image8 psf_map_image(const std::vector<FieldPsf>& psfs, ColourScale scale, const std::string& unit,
                     const std::string& field_unit);

// The wavefronts at `wavelength_nm` (those measured at it).
Image8 opd_map_image(const WavefrontFigures& figures, double wavelength_nm,
                     const std::string& field_unit);

}  // namespace lenslab
