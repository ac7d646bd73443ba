#pragma once
// The bench's figures (analysis/figures/diagram_canvas.h) painted with QPainter: the same layout
// the command line writes as SVG or PNG, scaled to fit a widget, so editor and CLI agree.

#include <QPainter>

#include "analysis/figures/diagram_canvas.h"

namespace lenslab::gui {

// Lays `figure` out `layout_width` pixels wide (at least `min_height` high), as
// `lenslab analyze` does, and paints it centred in `area`, scaled to fit with its aspect.
void paint_bench_figure(QPainter& painter, const RayDiagram& figure, const QRectF& area,
                        double layout_width, double min_height);

}  // namespace lenslab::gui
