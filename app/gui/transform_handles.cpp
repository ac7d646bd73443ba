#include "transform_handles.h"

#include <QPainterPath>
#include <cmath>
#include <numbers>

namespace lenslab::gui {

namespace {

constexpr double kArrowPixels = 90;  // arrow length on screen
constexpr double kRingPixels = 62;   // ring radius on screen
constexpr double kGripPixels = 7;    // how near the mouse must come to a handle
constexpr int kRingSegments = 72;

const Vec3 kHandleAxes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

double handle_distance_to_segment(const QPointF& p, const QPointF& a, const QPointF& b) {
    const QPointF ab = b - a;
    const double len2 = QPointF::dotProduct(ab, ab);
    const double t = len2 > 0 ? std::clamp(QPointF::dotProduct(p - a, ab) / len2, 0.0, 1.0) : 0;
    const QPointF d = p - (a + ab * t);
    return std::hypot(d.x(), d.y());
}

}  // namespace

QColor handle_colour(int axis) {
    static const QColor colours[3] = {QColor(230, 70, 70), QColor(90, 200, 80),
                                      QColor(80, 130, 245)};
    return colours[axis];
}

TransformHandles::TransformHandles(const ViewCamera& view, const Vec3& pivot, bool rotates)
    : m_pivot(pivot) {
    const std::optional<QPointF> centre = view.project(pivot);
    if (!centre) return;
    m_valid = true;
    m_centre = *centre;
    const double upp = view.units_per_pixel(pivot);
    m_length = kArrowPixels * upp;
    const Vec3 to_eye = view.eye() - pivot;
    for (int a = 0; a < 3; ++a) {
        const Vec3& axis = kHandleAxes[a];
        m_axis_faces_eye[a] = dot(axis, to_eye) > 0;
        if (const std::optional<QPointF> tip = view.project(pivot + axis * m_length)) {
            const QPointF d = *tip - m_centre;
            m_arrows[a] = {m_centre, *tip, std::hypot(d.x(), d.y()) > 12};
        }
        if (!rotates) continue;
        // Two directions across the axis span its ring.
        const Vec3 e1 = kHandleAxes[(a + 1) % 3], e2 = kHandleAxes[(a + 2) % 3];
        const double radius = kRingPixels * upp;
        QPolygonF part;
        for (int i = 0; i <= kRingSegments; ++i) {
            const double t = 2 * std::numbers::pi * i / kRingSegments;
            const std::optional<QPointF> p =
                view.project(pivot + (e1 * std::cos(t) + e2 * std::sin(t)) * radius);
            if (p) {
                part << *p;
            } else if (!part.isEmpty()) {
                m_rings[a].push_back(part);
                part.clear();
            }
        }
        if (part.size() > 1) m_rings[a].push_back(part);
    }
}

void TransformHandles::paint(QPainter& painter, const Handle& active) const {
    if (!m_valid) return;
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    const auto colour = [&](HandleKind kind, int a) {
        return active.kind == kind && active.axis == a ? QColor(255, 220, 60) : handle_colour(a);
    };
    for (int a = 0; a < 3; ++a) {
        for (const QPolygonF& part : m_rings[a]) {
            painter.setPen(QPen(colour(HandleKind::Rotate, a), 2));
            painter.drawPolyline(part);
        }
    }
    for (int a = 0; a < 3; ++a) {
        const Arrow& arrow = m_arrows[a];
        if (!arrow.visible) continue;
        const QColor c = colour(HandleKind::Move, a);
        painter.setPen(QPen(c, 3, Qt::SolidLine, Qt::RoundCap));
        painter.drawLine(arrow.base, arrow.tip);
        // The head: a triangle along the shaft's screen direction.
        const QPointF d = arrow.tip - arrow.base;
        const QPointF u = d / std::hypot(d.x(), d.y());
        const QPointF n(-u.y(), u.x());
        QPainterPath head;
        head.moveTo(arrow.tip + u * 12);
        head.lineTo(arrow.tip + n * 6);
        head.lineTo(arrow.tip - n * 6);
        head.closeSubpath();
        painter.setPen(Qt::NoPen);
        painter.setBrush(c);
        painter.drawPath(head);
    }
    painter.setPen(QPen(Qt::white, 1));
    painter.setBrush(QColor(255, 255, 255, 160));
    painter.drawEllipse(m_centre, 3.5, 3.5);
    painter.restore();
}

Handle TransformHandles::at(const QPointF& widget) const {
    if (!m_valid) return {};
    for (int a = 0; a < 3; ++a) {
        const Arrow& arrow = m_arrows[a];
        // The shaft's inner fifth is left to the rings and the object under it.
        if (arrow.visible &&
            handle_distance_to_segment(widget, arrow.base + (arrow.tip - arrow.base) * 0.2,
                                       arrow.tip + (arrow.tip - arrow.base) * 0.15) <= kGripPixels)
            return {HandleKind::Move, a};
    }
    for (int a = 0; a < 3; ++a) {
        for (const QPolygonF& part : m_rings[a]) {
            for (int i = 0; i + 1 < part.size(); ++i) {
                if (handle_distance_to_segment(widget, part[i], part[i + 1]) <= kGripPixels * 0.8)
                    return {HandleKind::Rotate, a};
            }
        }
    }
    return {};
}

double TransformHandles::move_distance(int axis, const QPointF& from, const QPointF& to) const {
    const Arrow& arrow = m_arrows[axis];
    const QPointF d = arrow.tip - arrow.base;  // m_length scene units on screen
    const double len2 = QPointF::dotProduct(d, d);
    if (!arrow.visible || len2 <= 0) return 0;
    return QPointF::dotProduct(to - from, d) / len2 * m_length;
}

double TransformHandles::rotate_angle(int axis, const QPointF& from, const QPointF& to) const {
    const QPointF a = from - m_centre, b = to - m_centre;
    // Widget y runs down: a positive screen angle is clockwise as seen.
    double swept = std::atan2(b.y(), b.x()) - std::atan2(a.y(), a.x());
    if (swept > std::numbers::pi) swept -= 2 * std::numbers::pi;
    if (swept < -std::numbers::pi) swept += 2 * std::numbers::pi;
    // Seen from where +axis points, an anticlockwise sweep is a positive turn.
    return m_axis_faces_eye[axis] ? -swept : swept;
}

double TransformHandles::move_snap() const {
    return std::pow(10.0, std::floor(std::log10(m_length))) / 10;
}

double TransformHandles::rotate_snap() { return std::numbers::pi / 12; }

QPointF TransformHandles::arrow_grip(int axis) const {
    const Arrow& arrow = m_arrows[axis];
    return arrow.base + (arrow.tip - arrow.base) * 0.75;
}

std::optional<QPointF> TransformHandles::ring_grip(int axis) const {
    // The ring's point farthest from every arrow: the middle of its longest visible part.
    for (const QPolygonF& part : m_rings[axis]) {
        for (int i = part.size() / 8; i < part.size(); i += std::max<int>(1, part.size() / 16)) {
            const Handle h = at(part[i]);
            if (h.kind == HandleKind::Rotate && h.axis == axis) return part[i];
        }
    }
    return std::nullopt;
}

}  // namespace lenslab::gui
