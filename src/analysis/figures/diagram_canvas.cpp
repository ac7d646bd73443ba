#include "analysis/figures/diagram_canvas.h"

#include <algorithm>

namespace lenslab {

namespace {

constexpr double kMargin = 24, kTop = 64, kBottom = 56;
constexpr DiagramColour kCanvasInk{30, 30, 30};

}  // namespace

double diagram_height(const RayDiagram& d, double width, double min_height) {
    // From the aspect at full width, so the drawing fills the picture's width.
    const double scale = (width - 2 * kMargin) / (d.z_max - d.z_min);
    return std::max(min_height, kTop + kBottom + (d.y_max - d.y_min) * scale);
}

void draw_diagram(const RayDiagram& d, DiagramCanvas& canvas, double width, double min_height) {
    const double height = diagram_height(d, width, min_height);
    const DiagramView v = fit_diagram(d, width, height, kMargin, kTop, kBottom);
    canvas.begin(width, height);
    // Rays leaving a diverging lens run out of the frame: clip them to the diagram's box.
    canvas.clip(v.x(d.z_min), v.y(d.y_max), (d.z_max - d.z_min) * v.scale,
                (d.y_max - d.y_min) * v.scale);
    for (const DiagramPath& p : d.paths) {
        std::vector<CanvasPoint> points;
        for (const DiagramPoint& q : p.points) points.push_back({v.x(q.z), v.y(q.y)});
        canvas.path(points, p);
    }
    canvas.unclip();
    for (const DiagramDot& dot : d.dots) {
        canvas.dot({v.x(dot.at.z), v.y(dot.at.y)}, dot.radius, dot.colour);
    }
    for (const DiagramText& t : d.labels) {
        canvas.text({v.x(t.at.z) + t.dx, v.y(t.at.y) + t.dy}, t.text, t.size, t.anchor, t.colour);
    }
    // Title, legend (top right) and scale bar (bottom left).
    canvas.text({kMargin, 26}, d.title, 16, DiagramText::Anchor::Start, kCanvasInk);
    double x = width - kMargin;
    for (auto it = d.legend.rbegin(); it != d.legend.rend(); ++it) {
        const double text_width = 7.0 * it->text.size();
        x -= text_width;
        canvas.text({x, 50}, it->text, 12, DiagramText::Anchor::Start, kCanvasInk);
        canvas.line({x - 30, 46}, {x - 6, 46}, it->colour, 2.5);
        x -= 48;
    }
    canvas.text({kMargin, 50}, d.subtitle, 12, DiagramText::Anchor::Start, kCanvasInk);
    if (d.scale_bar > 0) {
        const double bar = d.scale_bar * v.scale;
        const double y_bar = height - 22;
        canvas.line({kMargin, y_bar}, {kMargin + bar, y_bar}, kCanvasInk, 2);
        for (double xe : {kMargin, kMargin + bar}) {
            canvas.line({xe, y_bar - 5}, {xe, y_bar + 5}, kCanvasInk, 2);
        }
        canvas.text({kMargin + bar + 8, y_bar + 4}, d.scale_bar_label, 12,
                    DiagramText::Anchor::Start, kCanvasInk);
    }
    canvas.end();
}

}  // namespace lenslab
