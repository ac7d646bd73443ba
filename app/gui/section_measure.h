#pragma once
// The section view's measuring tools, in the plane's own coordinates: a ruler (a length and
// its slope) and a protractor whose two arms lie along pieces of the drawing (a ray's
// segment, as the light goes, or an edge of a cross-section), so an angle reads exactly what
// the tracer computed; and their painting over the drawing.

#include <QPainter>
#include <QString>
#include <optional>
#include <vector>

#include "analysis/figures/ray_diagram.h"

namespace lenslab::gui {

// A straight piece of the drawing from a to b.
struct SectionArm {
    DiagramPoint a, b;
    bool directed = true;  // a ray's segment (a to b as the light goes); false: a surface's edge
    // On a start ray's own path (SectionRayPath::start >= 0): which, so the arm follows the
    // ray through edits (a prism turned under the protractor): the start index, the
    // wavelength and the segment, counted from the path's start (>= 0) or end (< 0).
    int ray = -1;
    double nm = 0;
    int segment = 0;
};

// The protractor's reading in degrees: between two rays' directions, how far the light
// turned (0-180); with a surface's edge, the smaller angle between the lines (0-90).
double protractor_degrees(const SectionArm& first, const SectionArm& second);

// Where the two arms' lines cross; nothing for parallel lines.
std::optional<DiagramPoint> arms_crossing(const SectionArm& first, const SectionArm& second);

// The ruler's text: its length in the scene's units and its angle from the horizontal.
QString ruler_text(const DiagramPoint& a, const DiagramPoint& b);

// The measurements as a drawing in the plane, which the view paints and the SVG export
// writes: `pixel` is one pixel's length in the plane (ticks, the arc and the readings' offsets
// keep their size on screen).
struct MeasureDrawing {
    std::vector<DiagramPath> paths;
    std::vector<DiagramText> labels;
};
// The ruler from a to b: its line, a tick across each end and the reading.
MeasureDrawing ruler_drawing(const DiagramPoint& a, const DiagramPoint& b, double pixel);
// The protractor's arms (the second may be missing while it waits for a click), their lines
// extended to where they cross, the arc between them there and the reading.
MeasureDrawing protractor_drawing(const SectionArm& first, const std::optional<SectionArm>& second,
                                  double pixel);
// Paints a drawing placed by `view`, the readings on white boxes so they read over rays.
void paint_measure(QPainter& painter, const DiagramView& view, const MeasureDrawing& drawing);

}  // namespace lenslab::gui
