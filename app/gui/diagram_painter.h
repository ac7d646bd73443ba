#pragma once
// Paints a RayDiagram (analysis/figures/ray_diagram.h) with QPainter: the editor's ray diagram and
// section view draw the same model the SVG writer exports.

#include <QPainter>
#include <optional>

#include "analysis/figures/ray_diagram.h"

namespace lenslab::gui {

// Margins around the drawing, in pixels: the legend above, the scale bar below.
inline constexpr double kDiagramTop = 28, kDiagramBottom = 30, kDiagramMargin = 12;

// The placement that fits `d` into `size` (true aspect).
DiagramView fit_diagram_to(const RayDiagram& d, const QSizeF& size);

// Paints `d` on a white background of `size`, placed by `view`.
void paint_diagram(QPainter& painter, const RayDiagram& d, const QSizeF& size,
                   const DiagramView& view);

}  // namespace lenslab::gui
