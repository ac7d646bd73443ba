#include "analysis/ray_diagram_svg.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace lenslab {

namespace {

constexpr double kMargin = 24, kTop = 64, kBottom = 56;

std::string colour(const DiagramColour& c) {
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", c.r, c.g, c.b);
    return buffer;
}

std::string num(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.2f", v);
    return buffer;
}

std::string escape(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

const char* anchor(DiagramText::Anchor a) {
    switch (a) {
        case DiagramText::Anchor::Start:
            return "start";
        case DiagramText::Anchor::End:
            return "end";
        case DiagramText::Anchor::Middle:
            break;
    }
    return "middle";
}

}  // namespace

std::string ray_diagram_svg(const RayDiagram& d, double width, double min_height) {
    // Height from the aspect at full width, so the drawing fills the picture's width.
    const double scale = (width - 2 * kMargin) / (d.z_max - d.z_min);
    const double height = std::max(min_height, kTop + kBottom + (d.y_max - d.y_min) * scale);
    const DiagramView v = fit_diagram(d, width, height, kMargin, kTop, kBottom);

    std::ostringstream s;
    s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(width) << "\" height=\""
      << num(height) << "\" viewBox=\"0 0 " << num(width) << " " << num(height)
      << "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n";
    s << "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
    // Rays leaving a diverging lens run out of the frame: clip them to the diagram's box.
    s << "<clipPath id=\"frame\"><rect x=\"" << num(v.x(d.z_min)) << "\" y=\"" << num(v.y(d.y_max))
      << "\" width=\"" << num((d.z_max - d.z_min) * v.scale) << "\" height=\""
      << num((d.y_max - d.y_min) * v.scale) << "\"/></clipPath>\n<g clip-path=\"url(#frame)\">\n";
    for (const DiagramPath& p : d.paths) {
        s << "<" << (p.closed ? "polygon" : "polyline") << " points=\"";
        for (const DiagramPoint& q : p.points) s << num(v.x(q.z)) << "," << num(v.y(q.y)) << " ";
        s << "\" fill=\"" << (p.filled ? colour(p.fill) : "none") << "\"";
        if (p.filled && p.fill_opacity < 1) s << " fill-opacity=\"" << num(p.fill_opacity) << "\"";
        s << " stroke=\"" << colour(p.stroke) << "\" stroke-width=\"" << num(p.width) << "\"";
        if (p.stroke_opacity < 1) s << " stroke-opacity=\"" << num(p.stroke_opacity) << "\"";
        if (p.dash > 0)
            s << " stroke-dasharray=\"" << num(p.dash) << " " << num(0.6 * p.dash) << "\"";
        s << " stroke-linejoin=\"round\"/>\n";
    }
    s << "</g>\n";
    for (const DiagramDot& dot : d.dots) {
        s << "<circle cx=\"" << num(v.x(dot.at.z)) << "\" cy=\"" << num(v.y(dot.at.y)) << "\" r=\""
          << num(dot.radius) << "\" fill=\"" << colour(dot.colour) << "\"/>\n";
    }
    for (const DiagramText& t : d.labels) {
        s << "<text x=\"" << num(v.x(t.at.z) + t.dx) << "\" y=\"" << num(v.y(t.at.y) + t.dy)
          << "\" font-size=\"" << num(t.size) << "\" text-anchor=\"" << anchor(t.anchor)
          << "\" fill=\"" << colour(t.colour) << "\">" << escape(t.text) << "</text>\n";
    }
    // Title, legend (top right) and scale bar (bottom left).
    s << "<text x=\"" << num(kMargin) << "\" y=\"26\" font-size=\"16\" fill=\"#1e1e1e\">"
      << escape(d.title) << "</text>\n";
    double x = width - kMargin;
    for (auto it = d.legend.rbegin(); it != d.legend.rend(); ++it) {
        const double text_width = 7.0 * it->text.size();
        x -= text_width;
        s << "<text x=\"" << num(x) << "\" y=\"50\" font-size=\"12\" fill=\"#1e1e1e\">"
          << escape(it->text) << "</text>\n";
        s << "<line x1=\"" << num(x - 30) << "\" y1=\"46\" x2=\"" << num(x - 6)
          << "\" y2=\"46\" stroke=\"" << colour(it->colour) << "\" stroke-width=\"2.5\"/>\n";
        x -= 48;
    }
    s << "<text x=\"" << num(kMargin) << "\" y=\"50\" font-size=\"12\" fill=\"#1e1e1e\">"
      << escape(d.subtitle) << "</text>\n";
    if (d.scale_bar > 0) {
        const double bar = d.scale_bar * v.scale;
        const double y_bar = height - 22;
        s << "<line x1=\"" << num(kMargin) << "\" y1=\"" << num(y_bar) << "\" x2=\""
          << num(kMargin + bar) << "\" y2=\"" << num(y_bar)
          << "\" stroke=\"#1e1e1e\" stroke-width=\"2\"/>\n";
        for (double xe : {kMargin, kMargin + bar}) {
            s << "<line x1=\"" << num(xe) << "\" y1=\"" << num(y_bar - 5) << "\" x2=\"" << num(xe)
              << "\" y2=\"" << num(y_bar + 5) << "\" stroke=\"#1e1e1e\" stroke-width=\"2\"/>\n";
        }
        s << "<text x=\"" << num(kMargin + bar + 8) << "\" y=\"" << num(y_bar + 4)
          << "\" font-size=\"12\" fill=\"#1e1e1e\">" << escape(d.scale_bar_label) << "</text>\n";
    }
    s << "</svg>\n";
    return s.str();
}

}  // namespace lenslab
