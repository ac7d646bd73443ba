#include "section_widget.h"

#include <QMouseEvent>
#include <QPainter>
#include <QSaveFile>
#include <QWheelEvent>
#include <cmath>

#include "analysis/figures/ray_diagram_svg.h"
#include "diagram_painter.h"
#include "json_pointer.h"
#include "scene/object_types.h"
#include "scene_document.h"

namespace lenslab::gui {

namespace {

// Rays across the selected lens's aperture: the interactive case.
constexpr int kSectionBeamRays = 15;
// How near (pixels) a click must come to a flat object's section line to pick it.
constexpr double kSectionPickPixels = 5;

double distance_to_segment(const DiagramPoint& p, const DiagramPoint& a, const DiagramPoint& b) {
    const double dz = b.z - a.z, dy = b.y - a.y;
    const double len2 = dz * dz + dy * dy;
    const double t =
        len2 > 0 ? std::clamp(((p.z - a.z) * dz + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0;
    return std::hypot(p.z - a.z - t * dz, p.y - a.y - t * dy);
}

}  // namespace

SectionWidget::SectionWidget(SceneDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document) {
    setObjectName("section_view");
    setMinimumSize(320, 240);
    connect(m_document, &SceneDocument::changed, this, &SectionWidget::refresh);
    refresh();
}

void SectionWidget::show_pointer(const QString& pointer) {
    m_pointer = pointer;
    m_refit = true;
    refresh();
}

void SectionWidget::set_plane_choice(SectionPlaneChoice choice) {
    m_plane_choice = choice;
    m_refit = true;
    refresh();
}

void SectionWidget::refresh() {
    const Scene& scene = m_document->scene();
    const QStringList tokens = split_pointer(m_pointer);  // {"objects", "3"}: an object
    bool is_object = tokens.size() == 2 && tokens[0] == "objects";
    const int entry = is_object ? tokens[1].toInt(&is_object) : -1;
    m_selected = -1;
    for (int i = 0; i < int(scene.objects.size()) && m_selected < 0 && is_object; ++i) {
        if (scene.objects[i].source == entry) m_selected = i;
    }
    // While dragging, the plane stays put: the object moves within it.
    if (m_drag_object < 0) m_plane = section_plane(scene, m_selected, m_plane_choice);
    SectionViewOptions options;
    options.rays.beam = default_section_beam(scene, m_selected, m_plane, kSectionBeamRays);
    m_section = make_section_view(scene, m_plane, options);
    // The frame stays put through edits (a dragged object moves across it) and is fitted
    // again to a new selection or a scene with other objects.
    const int objects = int(scene.objects.size());
    if (m_refit || objects != m_fitted_objects) {
        m_extent = focus_extent(m_section, m_selected);
        m_fitted_objects = objects;
        m_refit = false;
    }
    m_section.extent = m_extent;
    m_diagram = section_diagram(scene, m_section, m_selected);
    update();
}

DiagramView SectionWidget::placement() const {
    return m_drag_object >= 0 ? m_drag_view : fit_diagram_to(m_diagram, size());
}

QPointF SectionWidget::to_widget(const DiagramPoint& p) const {
    const DiagramView v = placement();
    return {v.x(p.z), v.y(p.y)};
}

DiagramPoint SectionWidget::to_plane(const QPointF& p) const {
    const DiagramView v = placement();
    return {v.z_min + (p.x() - v.left) / v.scale, v.y_max - (p.y() - v.top) / v.scale};
}

int SectionWidget::object_at(const QPointF& pixel) const {
    const Scene& scene = m_document->scene();
    const DiagramPoint p = to_plane(pixel);
    const double reach = kSectionPickPixels / placement().scale;
    // The selected object first, then the last drawn (on top).
    std::vector<int> order;
    for (auto it = m_section.objects.rbegin(); it != m_section.objects.rend(); ++it)
        order.push_back(it->object);
    if (m_selected >= 0) order.insert(order.begin(), m_selected);
    for (int object : order) {
        const Shape& shape = *scene.objects[object].shape;
        if (shape.is_closed() && shape.contains(m_plane.at(p))) return object;
    }
    for (const SectionObject& o : m_section.objects) {
        for (const SectionCurve& c : o.curves) {
            for (size_t i = 0; i + 1 < c.points.size(); ++i) {
                if (distance_to_segment(p, c.points[i], c.points[i + 1]) < reach) return o.object;
            }
        }
    }
    return -1;
}

void SectionWidget::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    paint_diagram(painter, m_diagram, size(), placement());
}

void SectionWidget::mousePressEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton) return;
    m_press = event->position();
    m_dragged = false;
    m_drag_object = -1;
    const int object = object_at(m_press);
    if (object < 0 || m_document->scene().objects[object].source < 0) return;
    m_drag_view = fit_diagram_to(m_diagram, size());
    m_drag_object = object;
    m_before = m_document->json();
}

void SectionWidget::mouseMoveEvent(QMouseEvent* event) {
    if (m_drag_object < 0) return;
    const QPointF at = event->position();
    if (!m_dragged && (at - m_press).manhattanLength() < 4) return;
    m_dragged = true;
    const DiagramPoint from = to_plane(m_press), to = to_plane(at);
    const Vec3 offset = m_plane.u * (to.z - from.z) + m_plane.v * (to.y - from.y);
    const int entry = m_document->scene().objects[m_drag_object].source;
    nlohmann::json edited = m_before;
    nlohmann::json& element = edited["objects"][size_t(entry)];
    const ObjectTypeEntry* kind = find_object_type(element.value("type", ""));
    if (!kind) return;
    element = moved_element(kind->spec(), element, offset);
    if (!m_document->preview(edited)) emit edit_refused(tr("Cannot move the object there."));
}

void SectionWidget::mouseReleaseEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton) return;
    const int object = m_drag_object;
    m_drag_object = -1;
    if (m_dragged) {
        const std::string name = m_document->scene().objects[object].name;
        m_document->commit_preview(m_before, tr("Move %1").arg(QString::fromStdString(name)));
        m_dragged = false;
        update();  // placed by the widget's size again, not the press's
    } else {
        emit object_picked(object_at(event->position()));
    }
}

void SectionWidget::wheelEvent(QWheelEvent* event) {
    if (m_drag_object >= 0) return;
    const double factor = std::pow(0.85, event->angleDelta().y() / 120.0);
    const DiagramPoint at = to_plane(event->position());
    const auto scale = [&](double v, double centre) { return centre + (v - centre) * factor; };
    m_extent = {scale(m_extent.a_min, at.z), scale(m_extent.a_max, at.z),
                scale(m_extent.b_min, at.y), scale(m_extent.b_max, at.y)};
    m_section.extent = m_extent;
    m_diagram.z_min = m_extent.a_min, m_diagram.z_max = m_extent.a_max;
    m_diagram.y_min = m_extent.b_min, m_diagram.y_max = m_extent.b_max;
    update();
}

bool SectionWidget::export_svg(const QString& path, QString* error) const {
    const std::string svg = ray_diagram_svg(m_diagram);
    QSaveFile out(path);
    if (out.open(QIODevice::WriteOnly) &&
        out.write(svg.data(), qint64(svg.size())) == qint64(svg.size()) && out.commit())
        return true;
    if (error) *error = tr("Cannot write %1: %2").arg(path, out.errorString());
    return false;
}

}  // namespace lenslab::gui
