#pragma once
// The Monte Carlo of `lenslab tolerance` as a figure (`--figure FILE`, SVG or PNG): the
// histogram of the made lenses' criterion beside their cumulative yield (the share of lenses
// at or below each criterion), the nominal marked on both.

#include "analysis/figures/ray_diagram.h"
#include "optimize/tolerance.h"

namespace lenslab {

// `unit`: the system's length unit for the axis labels ("mm"; "" for none known).
RayDiagram tolerance_figure(const ToleranceReport& report, const std::string& unit);

}  // namespace lenslab
