#pragma once
// The picture of a ray diagram (ray_diagram.h) laid out once and drawn on any canvas: the
// SVG writer (ray_diagram_svg.h) and the PNG image (ray_diagram_image.h) are two canvases of
// the same layout, so both show the same picture.

#include <string>
#include <vector>

#include "analysis/figures/ray_diagram.h"

namespace lenslab {

struct CanvasPoint {
    double x = 0, y = 0;  // pixels, y down the picture
};

class DiagramCanvas {
public:
    virtual ~DiagramCanvas() = default;
    virtual void begin(double width, double height) = 0;
    // Paths drawn between clip() and unclip() are cut to that rectangle.
    virtual void clip(double x, double y, double width, double height) = 0;
    virtual void unclip() = 0;
    // `style` gives the stroke, fill, dash and whether the path is closed; its points are
    // replaced by `points`, in pixels.
    virtual void path(const std::vector<CanvasPoint>& points, const DiagramPath& style) = 0;
    virtual void dot(CanvasPoint at, double radius, DiagramColour colour) = 0;
    virtual void line(CanvasPoint a, CanvasPoint b, DiagramColour colour, double width) = 0;
    // `at` is the baseline's start, middle or end as `anchor` says.
    virtual void text(CanvasPoint at, const std::string& text, double size,
                      DiagramText::Anchor anchor, DiagramColour colour) = 0;
    virtual void end() = 0;
};

// The height of the picture draw_diagram lays the diagram out in, `width` pixels wide.
double diagram_height(const RayDiagram& diagram, double width, double min_height);

// Lays the diagram out in a picture `width` pixels wide (its height from the diagram's
// aspect, at least `min_height`) and draws it on `canvas`.
void draw_diagram(const RayDiagram& diagram, DiagramCanvas& canvas, double width,
                  double min_height);

}  // namespace lenslab
