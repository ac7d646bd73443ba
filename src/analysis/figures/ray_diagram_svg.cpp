#include "analysis/figures/ray_diagram_svg.h"

#include <cstdio>
#include <sstream>

#include "analysis/figures/diagram_canvas.h"

namespace lenslab {

namespace {

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

class SvgCanvas : public DiagramCanvas {
public:
    void begin(double width, double height) override {
        s_ << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(width) << "\" height=\""
           << num(height) << "\" viewBox=\"0 0 " << num(width) << " " << num(height)
           << "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n";
        s_ << "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
    }
    void clip(double x, double y, double width, double height) override {
        s_ << "<clipPath id=\"frame\"><rect x=\"" << num(x) << "\" y=\"" << num(y) << "\" width=\""
           << num(width) << "\" height=\"" << num(height)
           << "\"/></clipPath>\n<g clip-path=\"url(#frame)\">\n";
    }
    void unclip() override { s_ << "</g>\n"; }
    void path(const std::vector<CanvasPoint>& points, const DiagramPath& p) override {
        s_ << "<" << (p.closed ? "polygon" : "polyline") << " points=\"";
        for (const CanvasPoint& q : points) s_ << num(q.x) << "," << num(q.y) << " ";
        s_ << "\" fill=\"" << (p.filled ? colour(p.fill) : "none") << "\"";
        if (p.filled && p.fill_opacity < 1) s_ << " fill-opacity=\"" << num(p.fill_opacity) << "\"";
        s_ << " stroke=\"" << colour(p.stroke) << "\" stroke-width=\"" << num(p.width) << "\"";
        if (p.stroke_opacity < 1) s_ << " stroke-opacity=\"" << num(p.stroke_opacity) << "\"";
        if (p.dash > 0) {
            s_ << " stroke-dasharray=\"" << num(p.dash) << " " << num(0.6 * p.dash) << "\"";
        }
        s_ << " stroke-linejoin=\"round\"/>\n";
    }
    void dot(CanvasPoint at, double radius, DiagramColour c) override {
        s_ << "<circle cx=\"" << num(at.x) << "\" cy=\"" << num(at.y) << "\" r=\"" << num(radius)
           << "\" fill=\"" << colour(c) << "\"/>\n";
    }
    void line(CanvasPoint a, CanvasPoint b, DiagramColour c, double width) override {
        s_ << "<line x1=\"" << num(a.x) << "\" y1=\"" << num(a.y) << "\" x2=\"" << num(b.x)
           << "\" y2=\"" << num(b.y) << "\" stroke=\"" << colour(c) << "\" stroke-width=\""
           << num(width) << "\"/>\n";
    }
    void text(CanvasPoint at, const std::string& text, double size, DiagramText::Anchor a,
              DiagramColour c) override {
        s_ << "<text x=\"" << num(at.x) << "\" y=\"" << num(at.y) << "\" font-size=\"" << num(size)
           << "\" text-anchor=\"" << anchor(a) << "\" fill=\"" << colour(c) << "\">" << escape(text)
           << "</text>\n";
    }
    void end() override { s_ << "</svg>\n"; }
    std::string str() const { return s_.str(); }

private:
    std::ostringstream s_;
};

}  // namespace

std::string ray_diagram_svg(const RayDiagram& d, double width, double min_height) {
    SvgCanvas canvas;
    draw_diagram(d, canvas, width, min_height);
    return canvas.str();
}

}  // namespace lenslab
