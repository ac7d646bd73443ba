#include "analysis/figures/ray_diagram_image.h"

#include <algorithm>
#include <cmath>

#include "analysis/figures/diagram_canvas.h"
#include "image/bitmap_font.h"

namespace lenslab {

namespace {

class ImageCanvas : public DiagramCanvas {
public:
    void begin(double width, double height) override {
        image_.width = static_cast<int>(std::lround(width));
        image_.height = static_cast<int>(std::lround(height));
        image_.rgb.assign(size_t(image_.width) * size_t(image_.height) * 3, 255);
        unclip();
    }
    void clip(double x, double y, double width, double height) override {
        x0_ = x;
        y0_ = y;
        x1_ = x + width;
        y1_ = y + height;
    }
    void unclip() override {
        x0_ = y0_ = 0;
        x1_ = image_.width;
        y1_ = image_.height;
    }
    void path(const std::vector<CanvasPoint>& points, const DiagramPath& p) override {
        if (points.empty()) return;
        if (p.filled) fill(points, p.fill, p.fill_opacity);
        std::vector<CanvasPoint> outline = points;
        if (p.closed) outline.push_back(points.front());
        // Dashes run on along the whole path: `dash` pixels drawn, 0.6 dash left out.
        double along = 0;
        for (size_t i = 1; i < outline.size(); ++i) {
            stroke(outline[i - 1], outline[i], p.stroke, p.stroke_opacity, p.width, p.dash, along);
        }
    }
    void dot(CanvasPoint at, double radius, DiagramColour c) override { disc(at, radius, c, 1); }
    void line(CanvasPoint a, CanvasPoint b, DiagramColour c, double width) override {
        double along = 0;
        stroke(a, b, c, 1, width, 0, along);
    }
    void text(CanvasPoint at, const std::string& text, double size, DiagramText::Anchor anchor,
              DiagramColour c) override {
        const int scale = size >= 14 ? 2 : 1;
        double x = at.x;
        const int w = text_width(text, scale);
        if (anchor == DiagramText::Anchor::Middle) x -= 0.5 * w;
        if (anchor == DiagramText::Anchor::End) x -= w;
        const unsigned char rgb[3] = {static_cast<unsigned char>(c.r),
                                      static_cast<unsigned char>(c.g),
                                      static_cast<unsigned char>(c.b)};
        // The baseline at `at`: the glyphs' seventh row sits on it.
        draw_text(image_, static_cast<int>(std::lround(x)),
                  static_cast<int>(std::lround(at.y)) - 7 * scale, text, rgb, scale);
    }
    void end() override {}
    Image8 take() { return std::move(image_); }

private:
    void blend(int x, int y, DiagramColour c, double alpha) {
        if (x < x0_ || y < y0_ || x >= x1_ || y >= y1_ || x < 0 || y < 0 || x >= image_.width ||
            y >= image_.height) {
            return;
        }
        unsigned char* q = &image_.rgb[(size_t(y) * size_t(image_.width) + size_t(x)) * 3];
        const int rgb[3] = {c.r, c.g, c.b};
        for (int k = 0; k < 3; ++k) {
            q[k] = static_cast<unsigned char>(std::lround(q[k] + alpha * (rgb[k] - q[k])));
        }
    }
    void disc(CanvasPoint at, double radius, DiagramColour c, double alpha) {
        const double r = std::max(radius, 0.5);
        for (int y = int(std::floor(at.y - r)); y <= int(std::ceil(at.y + r)); ++y) {
            for (int x = int(std::floor(at.x - r)); x <= int(std::ceil(at.x + r)); ++x) {
                if (std::hypot(x + 0.5 - at.x, y + 0.5 - at.y) <= r) blend(x, y, c, alpha);
            }
        }
    }
    // A segment of width `width`, stamped every half pixel (where stamps of a translucent
    // stroke overlap it comes out a little darker).
    void stroke(CanvasPoint a, CanvasPoint b, DiagramColour c, double alpha, double width,
                double dash, double& along) {
        const double length = std::hypot(b.x - a.x, b.y - a.y);
        const int steps = std::max(1, static_cast<int>(std::ceil(2 * length)));
        const double r = 0.5 * std::max(width, 1.0);
        for (int i = 0; i <= steps; ++i) {
            const double t = double(i) / steps;
            const double s = along + t * length;
            if (dash > 0 && std::fmod(s, 1.6 * dash) > dash) continue;
            const CanvasPoint p{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
            if (r <= 0.75) {
                blend(static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y)), c,
                      alpha);
            } else {
                disc(p, r, c, alpha);
            }
        }
        along += length;
    }
    // Even-odd scanline fill through the pixel centres.
    void fill(const std::vector<CanvasPoint>& points, DiagramColour c, double alpha) {
        double top = points[0].y, bottom = points[0].y;
        for (const CanvasPoint& p : points) {
            top = std::min(top, p.y);
            bottom = std::max(bottom, p.y);
        }
        for (int y = int(std::floor(top)); y <= int(std::ceil(bottom)); ++y) {
            const double yc = y + 0.5;
            std::vector<double> xs;
            for (size_t i = 0; i < points.size(); ++i) {
                const CanvasPoint& p = points[i];
                const CanvasPoint& q = points[(i + 1) % points.size()];
                if ((p.y <= yc) != (q.y <= yc)) {
                    xs.push_back(p.x + (yc - p.y) / (q.y - p.y) * (q.x - p.x));
                }
            }
            std::sort(xs.begin(), xs.end());
            for (size_t k = 0; k + 1 < xs.size(); k += 2) {
                for (int x = int(std::ceil(xs[k] - 0.5)); x + 0.5 <= xs[k + 1]; ++x) {
                    blend(x, y, c, alpha);
                }
            }
        }
    }

    Image8 image_;
    double x0_ = 0, y0_ = 0, x1_ = 0, y1_ = 0;  // the clip rectangle
};

}  // namespace

Image8 ray_diagram_image(const RayDiagram& d, double width, double min_height) {
    ImageCanvas canvas;
    draw_diagram(d, canvas, width, min_height);
    return canvas.take();
}

}  // namespace lenslab
