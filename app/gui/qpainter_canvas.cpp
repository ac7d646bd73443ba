#include "qpainter_canvas.h"

#include <algorithm>

namespace lenslab::gui {

namespace {

QColor canvas_colour(const DiagramColour& c, double alpha = 1.0) {
    QColor q(c.r, c.g, c.b);
    q.setAlphaF(std::clamp(alpha, 0.0, 1.0));
    return q;
}

// A DiagramCanvas on a QPainter: begin() scales the layout's pixels into the target area.
class QPainterCanvas : public DiagramCanvas {
public:
    QPainterCanvas(QPainter& painter, const QRectF& area) : m_painter(painter), m_area(area) {}

    void begin(double width, double height) override {
        m_painter.save();
        m_painter.setRenderHint(QPainter::Antialiasing);
        const double scale = std::min(m_area.width() / width, m_area.height() / height);
        m_painter.translate(m_area.center().x() - 0.5 * width * scale,
                            m_area.center().y() - 0.5 * height * scale);
        m_painter.scale(scale, scale);
        m_painter.fillRect(QRectF(0, 0, width, height), Qt::white);
    }
    void clip(double x, double y, double width, double height) override {
        m_painter.setClipRect(QRectF(x, y, width, height));
    }
    void unclip() override { m_painter.setClipping(false); }
    void path(const std::vector<CanvasPoint>& points, const DiagramPath& style) override {
        QPolygonF polygon;
        for (const CanvasPoint& p : points) polygon << QPointF(p.x, p.y);
        QPen pen(canvas_colour(style.stroke, style.stroke_opacity), style.width);
        if (style.dash > 0)
            pen.setDashPattern({style.dash / style.width, style.dash / style.width});
        m_painter.setPen(style.width > 0 ? pen : QPen(Qt::NoPen));
        m_painter.setBrush(style.filled ? QBrush(canvas_colour(style.fill, style.fill_opacity))
                                        : QBrush(Qt::NoBrush));
        if (style.closed || style.filled) {
            m_painter.drawPolygon(polygon);
        } else {
            m_painter.drawPolyline(polygon);
        }
    }
    void dot(CanvasPoint at, double radius, DiagramColour colour) override {
        m_painter.setPen(Qt::NoPen);
        m_painter.setBrush(canvas_colour(colour));
        m_painter.drawEllipse(QPointF(at.x, at.y), radius, radius);
    }
    void line(CanvasPoint a, CanvasPoint b, DiagramColour colour, double width) override {
        m_painter.setPen(QPen(canvas_colour(colour), width));
        m_painter.drawLine(QPointF(a.x, a.y), QPointF(b.x, b.y));
    }
    void text(CanvasPoint at, const std::string& text, double size, DiagramText::Anchor anchor,
              DiagramColour colour) override {
        QFont font = m_painter.font();
        font.setPixelSize(std::max(1, int(size)));
        m_painter.setFont(font);
        m_painter.setPen(canvas_colour(colour));
        const QString label = QString::fromStdString(text);
        const double width = m_painter.fontMetrics().horizontalAdvance(label);
        double x = at.x;
        if (anchor == DiagramText::Anchor::Middle) x -= 0.5 * width;
        if (anchor == DiagramText::Anchor::End) x -= width;
        m_painter.drawText(QPointF(x, at.y), label);
    }
    void end() override { m_painter.restore(); }

private:
    QPainter& m_painter;
    QRectF m_area;
};

}  // namespace

void paint_bench_figure(QPainter& painter, const RayDiagram& figure, const QRectF& area,
                        double layout_width, double min_height) {
    QPainterCanvas canvas(painter, area);
    draw_diagram(figure, canvas, layout_width, min_height);
}

}  // namespace lenslab::gui
