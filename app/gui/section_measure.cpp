#include "section_measure.h"

#include <algorithm>
#include <cmath>
#include <numbers>

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

void paint_ruler(QPainter& painter, const DiagramView& view, const DiagramPoint& a,
                 const DiagramPoint& b) {
    const QPointF p = on_screen(view, a), q = on_screen(view, b);
    painter.setPen(QPen(kMeasureInk, 1.5));
    painter.drawLine(p, q);
    const QPointF along = q - p;
    const double n = std::hypot(along.x(), along.y());
    if (n > 0) {
        const QPointF tick = QPointF(-along.y(), along.x()) * (5 / n);
        painter.drawLine(p - tick, p + tick);
        painter.drawLine(q - tick, q + tick);
    }
    draw_reading(painter, q + QPointF(8, -6), ruler_text(a, b));
}

void paint_protractor(QPainter& painter, const DiagramView& view, const SectionArm& first,
                      const std::optional<SectionArm>& second) {
    painter.setPen(QPen(kMeasureInk, 3));
    painter.drawLine(on_screen(view, first.a), on_screen(view, first.b));
    if (!second) return;
    painter.drawLine(on_screen(view, second->a), on_screen(view, second->b));
    const std::optional<DiagramPoint> vertex = arms_crossing(first, *second);
    const double degrees = protractor_degrees(first, *second);
    const QString reading = QString("%1°").arg(degrees, 0, 'f', 2);
    if (!vertex) {
        draw_reading(painter, on_screen(view, second->b) + QPointF(8, -6), reading);
        return;
    }
    // Each arm's line extended (dashed) to the vertex, from its nearer end.
    QPen dashed(kMeasureInk, 1, Qt::DashLine);
    painter.setPen(dashed);
    const QPointF at = on_screen(view, *vertex);
    for (const SectionArm* arm : {&first, &*second}) {
        const QPointF a = on_screen(view, arm->a), b = on_screen(view, arm->b);
        const auto gap = [&](const QPointF& p) {
            return std::hypot(p.x() - at.x(), p.y() - at.y());
        };
        painter.drawLine(at, gap(a) < gap(b) ? a : b);
    }
    // The arc from the first arm's direction (continued past the vertex for a ray, so it
    // shows the turn) to the second's, the short way round.
    const double radius = 36;
    const double from = arm_angle(first) * kRadiansToDegrees;
    double span = arm_angle(*second) * kRadiansToDegrees - from;
    span = std::remainder(span, 360.0);
    if (!first.directed || !second->directed) {
        if (span > 90) span -= 180;
        if (span < -90) span += 180;
    }
    painter.setPen(QPen(kMeasureInk, 1.5));
    const QRectF circle(at - QPointF(radius, radius), QSizeF(2 * radius, 2 * radius));
    // Qt's angles run counter-clockwise on screen, as the plane's do with v up.
    painter.drawArc(circle, int(std::lround(from * 16)), int(std::lround(span * 16)));
    draw_reading(painter, at + QPointF(radius + 6, -radius / 2), reading);
}

}  // namespace lenslab::gui
