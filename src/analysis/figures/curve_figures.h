#pragma once
// The field curves and the chromatic focal shift drawn as charts (plot_panel.h), as
// lens-design programs plot them:
// - field curves: field on the vertical axis (0 at the bottom, the largest at the top); left,
//   the tangential (solid) and sagittal (dashed) foci from the image plane, per wavelength;
//   right, the distortion in %;
// - focal shift: the shift against wavelength across the band;
// - MTF: the tangential (solid) and sagittal (dashed) cuts beside the diffraction limit.

#include <string>

#include "analysis/aberrations/field_curves.h"
#include "analysis/aberrations/focal_shift.h"
#include "analysis/diffraction/diffraction_figures.h"
#include "analysis/diffraction/field_mtf.h"
#include "analysis/figures/ray_diagram.h"

namespace lenslab {

RayDiagram field_curves_figure(const FieldCurves& curves, const std::string& unit,
                               const std::string& field_unit);
RayDiagram focal_shift_figure(const FocalShift& shift, const std::string& unit);
// `unit`: the length unit of the frequencies' "cycles/unit" ("mm" for prescriptions).
RayDiagram mtf_figure(const DiffractionFigures& d, const std::string& unit);
// The MTF of every field (field_mtf.h), a colour each; `field_unit` follows each field's
// number in the legend ("°" for angles).
RayDiagram field_mtf_figure(const FieldMtfs& mtf, const std::string& unit,
                            const std::string& field_unit);

}  // namespace lenslab
