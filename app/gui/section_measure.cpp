#include "section_measure.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

namespace lenslab::gui {

namespace {

constexpr double kRadiansToDegrees = 180 / std::numbers::pi;
const QColor kMeasureInk(120, 40, 160);  // purple: apart from every ray colour but violet

double arm_angle(const SectionArm& arm) { return std::atan2(arm.b.y - arm.a.y, arm.b.z - arm.a.z); }

QPointF on_screen(const DiagramView& view, const DiagramPoint& p) {
    return {view.x(p.z), view.y(p.y)};
}

// Text on a white box, so it reads over rays.
void draw_reading(QPainter& painter, const QPointF& at, const QString& text) {
    const QRectF box = painter.fontMetrics().boundingRect(text).adjusted(-4, -2, 4, 2);
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(255, 255, 255, 230));
    painter.drawRect(box.translated(at));
    painter.setPen(kMeasureInk);
    painter.drawText(at, text);
}

}  // namespace

double protractor_degrees(const SectionArm& first, const SectionArm& second) {
    double turn = std::abs(arm_angle(second) - arm_angle(first)) * kRadiansToDegrees;
    if (turn > 180) turn = 360 - turn;
    if (!first.directed || !second.directed) turn = std::min(turn, 180 - turn);
    return turn;
}

std::optional<DiagramPoint> arms_crossing(const SectionArm& first, const SectionArm& second) {
    const double dz1 = first.b.z - first.a.z, dy1 = first.b.y - first.a.y;
    const double dz2 = second.b.z - second.a.z, dy2 = second.b.y - second.a.y;
    const double det = dz1 * dy2 - dy1 * dz2;
    if (std::abs(det) < 1e-12 * std::hypot(dz1, dy1) * std::hypot(dz2, dy2)) return std::nullopt;
    const double t = ((second.a.z - first.a.z) * dy2 - (second.a.y - first.a.y) * dz2) / det;
    return DiagramPoint{first.a.z + t * dz1, first.a.y + t * dy1};
}

QString ruler_text(const DiagramPoint& a, const DiagramPoint& b) {
    const double length = std::hypot(b.z - a.z, b.y - a.y);
    const double angle = std::atan2(b.y - a.y, b.z - a.z) * kRadiansToDegrees;
    return QObject::tr("%1 units, %2°").arg(length, 0, 'g', 5).arg(angle, 0, 'f', 2);
}

namespace {

DiagramColour measure_colour() {
    return {kMeasureInk.red(), kMeasureInk.green(), kMeasureInk.blue()};
}

void add_line(MeasureDrawing& d, std::vector<DiagramPoint> points, double width, double dash = 0) {
    DiagramPath path;
    path.points = std::move(points);
    path.stroke = measure_colour();
    path.width = width;
    path.dash = dash;
    d.paths.push_back(std::move(path));
}

void add_reading(MeasureDrawing& d, const DiagramPoint& at, double dx, double dy,
                 const QString& text) {
    DiagramText label;
    label.at = at;
    label.text = text.toStdString();
    label.colour = measure_colour();
    label.dx = dx;
    label.dy = dy;
    label.anchor = DiagramText::Anchor::Start;
    d.labels.push_back(std::move(label));
}

}  // namespace

MeasureDrawing ruler_drawing(const DiagramPoint& a, const DiagramPoint& b, double pixel) {
    MeasureDrawing d;
    add_line(d, {a, b}, 1.5);
    const double n = std::hypot(b.z - a.z, b.y - a.y);
    if (n > 0) {  // 5-pixel ticks across each end
        const DiagramPoint tick{-(b.y - a.y) * (5 * pixel / n), (b.z - a.z) * (5 * pixel / n)};
        for (const DiagramPoint& end : {a, b}) {
            add_line(d, {{end.z - tick.z, end.y - tick.y}, {end.z + tick.z, end.y + tick.y}}, 1.5);
        }
    }
    add_reading(d, b, 8, -6, ruler_text(a, b));
    return d;
}

MeasureDrawing protractor_drawing(const SectionArm& first, const std::optional<SectionArm>& second,
                                  double pixel) {
    MeasureDrawing d;
    add_line(d, {first.a, first.b}, 3);
    if (!second) return d;
    add_line(d, {second->a, second->b}, 3);
    const std::optional<DiagramPoint> vertex = arms_crossing(first, *second);
    const QString reading = QString("%1°").arg(protractor_degrees(first, *second), 0, 'f', 2);
    if (!vertex) {
        add_reading(d, second->b, 8, -6, reading);
        return d;
    }
    // Each arm's line extended (dashed) to the vertex, from its nearer end.
    for (const SectionArm* arm : {&first, &*second}) {
        const auto gap = [&](const DiagramPoint& p) {
            return std::hypot(p.z - vertex->z, p.y - vertex->y);
        };
        add_line(d, {*vertex, gap(arm->a) < gap(arm->b) ? arm->a : arm->b}, 1, 4);
    }
    // The arc from the first arm's direction (continued past the vertex for a ray, so it
    // shows the turn) to the second's, the short way round, 36 pixels out.
    const double radius_px = 36;
    const double from = arm_angle(first);
    double span = std::remainder(arm_angle(*second) - from, 2 * std::numbers::pi);
    if (!first.directed || !second->directed) {
        if (span > std::numbers::pi / 2) span -= std::numbers::pi;
        if (span < -std::numbers::pi / 2) span += std::numbers::pi;
    }
    constexpr int kArcSteps = 48;
    std::vector<DiagramPoint> arc;
    for (int i = 0; i <= kArcSteps; ++i) {
        const double angle = from + span * i / kArcSteps;
        arc.push_back({vertex->z + radius_px * pixel * std::cos(angle),
                       vertex->y + radius_px * pixel * std::sin(angle)});
    }
    add_line(d, std::move(arc), 1.5);
    add_reading(d, *vertex, radius_px + 6, -radius_px / 2, reading);
    return d;
}

void paint_measure(QPainter& painter, const DiagramView& view, const MeasureDrawing& drawing) {
    painter.setBrush(Qt::NoBrush);
    for (const DiagramPath& path : drawing.paths) {
        QPen pen(kMeasureInk, path.width);
        if (path.dash > 0) pen.setDashPattern({path.dash / path.width, path.dash / path.width});
        painter.setPen(pen);
        QPolygonF line;
        for (const DiagramPoint& p : path.points) line << on_screen(view, p);
        painter.drawPolyline(line);
    }
    for (const DiagramText& label : drawing.labels) {
        draw_reading(painter, on_screen(view, label.at) + QPointF(label.dx, label.dy),
                     QString::fromStdString(label.text));
    }
}

}  // namespace lenslab::gui
