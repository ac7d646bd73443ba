#pragma once
// The Monte Carlo of `lenslab tolerance` as a figure (`--figure FILE`, SVG or PNG): the
// histogram of the made lenses' criterion beside their cumulative yield (the share of lenses
// at or below each criterion), the nominal marked on both.

#include "analysis/figures/ray_diagram.h"
#include "optimize/tolerance.h"

namespace lenslab {

// `unit`: the system's length unit for the axis labels ("mm"; "" for none known).
RayDiagram tolerance_figure(const ToleranceReport& report, const std::string& unit);
// The figure's size in pixels as `lenslab tolerance --figure` writes it: two square panels
// side by side, as the bench's curves.
inline constexpr double kToleranceFigureWidth = 900, kToleranceFigureHeight = 420;

}  // namespace lenslab
