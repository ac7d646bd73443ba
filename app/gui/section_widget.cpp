#include "section_widget.h"

#include <QImage>
#include <QMouseEvent>
#include <QPainter>
#include <QSaveFile>
#include <QWheelEvent>
#include <cmath>

#include "analysis/figures/ray_diagram_svg.h"
#include "analysis/section/section_outline.h"
#include "analysis/section/section_ray_report.h"
#include "diagram_painter.h"
#include "json_pointer.h"
#include "scene/object_types.h"
#include "scene_document.h"

namespace lenslab::gui {

namespace {

// How near (pixels) a click must come to a line of the drawing to pick it.
constexpr double kSectionPickPixels = 5;
// Fit selection's room around the object, a fraction of its size on each side.
constexpr double kSectionFitRoom = 0.2;
// How far (pixels) the mouse moves before a press becomes a drag.
constexpr int kSectionDragPixels = 4;

double distance_to_segment(const DiagramPoint& p, const DiagramPoint& a, const DiagramPoint& b) {
    const double dz = b.z - a.z, dy = b.y - a.y;
    const double len2 = dz * dz + dy * dy;
    const double t =
        len2 > 0 ? std::clamp(((p.z - a.z) * dz + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0;
    return std::hypot(p.z - a.z - t * dz, p.y - a.y - t * dy);
}

// The middle of the bounding box of an object's cross-section (the object is under the
// mouse, so the plane cuts it).
DiagramPoint section_centre(const SectionView& view, int object) {
    const SectionExtent box = section_bounds(view, object).value_or(SectionExtent{});
    return {0.5 * (box.a_min + box.a_max), 0.5 * (box.b_min + box.b_max)};
}

}  // namespace

SectionWidget::SectionWidget(SceneDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document) {
    setObjectName("section_view");
    setMinimumSize(200, 100);
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
    m_refit_plane = true;
    refresh();
}

void SectionWidget::set_rays(int rays) {
    m_rays = std::max(rays, 1);
    refresh();
}

void SectionWidget::set_tool(SectionTool tool) {
    m_tool = tool;
    // A measuring tool starts afresh; Move keeps what was measured, to watch it through edits.
    if (tool != SectionTool::Move) {
        m_ruler_from.reset();
        m_ruler_to.reset();
        m_arms.clear();
    }
    setCursor(tool == SectionTool::Move ? Qt::ArrowCursor : Qt::CrossCursor);
    update();
}

void SectionWidget::fit_all() {
    m_refit = true;
    refresh();
}

void SectionWidget::fit_selection() {
    show_extent(focus_extent(m_section, m_selected, kSectionFitRoom));
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
    // While dragging, the plane stays put: the object moves within it. A newly selected
    // object with no axis of its own keeps the plane it lies in (a screen clicked beside a
    // lens), so the bench does not turn under the teacher's hand.
    const bool keep_plane =
        m_drag_object >= 0 || (!m_refit_plane && m_refit && m_has_plane &&
                               m_plane_choice == SectionPlaneChoice::Default && m_selected >= 0 &&
                               !section_plane_follows_axis(scene, m_selected) &&
                               !section_outline(*scene.objects[m_selected].shape, m_plane).empty());
    if (!keep_plane) m_plane = section_plane(scene, m_selected, m_plane_choice);
    m_has_plane = true;
    m_refit_plane = false;
    SectionViewOptions options;
    options.rays.rays_per_light = m_rays;
    // A beam across the selection: always along a lens's axis; across anything else only
    // when no light of the scene sends rays in the plane (a prism's own beam tells more).
    const bool lit = !section_start_rays(scene, m_plane, options.rays).empty();
    if (section_plane_follows_axis(scene, m_selected) || !lit)
        options.rays.beam = default_section_beam(scene, m_selected, m_plane, m_rays);
    // Light from left to right, as optics draws it (a plane of the axes keeps its sides).
    if (m_plane_choice == SectionPlaneChoice::Default && options.rays.beam &&
        dot(options.rays.beam->direction, m_plane.u) < 0) {
        m_plane.u = -m_plane.u;
    }
    m_section = make_section_view(scene, m_plane, options);
    // The frame stays put through edits (a dragged object moves across it) and is fitted
    // again, to everything, for a new selection or a scene with other objects.
    const int objects = int(scene.objects.size());
    if (keep_plane && m_drag_object < 0) m_refit = false;  // the same bench: the same frame
    if (m_refit || objects != m_fitted_objects) {
        m_fitted_objects = objects;
        m_refit = false;
        show_extent(m_section.extent);
    } else {
        show_extent(m_wanted);
    }
    // A clicked ray's read-out follows the edit, and so does a protractor laid on rays.
    if (m_inspected >= 0) inspect(m_inspected < int(m_section.rays.size()) ? m_inspected : -1);
    if (follow_rays(m_arms) && m_arms.size() == 2) {
        emit measured(tr("Protractor: %1°").arg(*protractor_reading(), 0, 'f', 2));
        update();
    }
}

void SectionWidget::show_extent(const SectionExtent& wanted) {
    // Widened about its middle to the shape of the drawing's area, so the drawing fills it.
    m_wanted = wanted;
    SectionExtent e = wanted;
    const double w = std::max(1.0, width() - 2 * kDiagramMargin);
    const double h = std::max(1.0, height() - kDiagramTop - kDiagramBottom);
    const double ew = e.a_max - e.a_min, eh = e.b_max - e.b_min;
    if (ew > 0 && eh > 0) {
        if (ew / eh < w / h) {
            const double grow = 0.5 * (eh * w / h - ew);
            e.a_min -= grow, e.a_max += grow;
        } else {
            const double grow = 0.5 * (ew * h / w - eh);
            e.b_min -= grow, e.b_max += grow;
        }
    }
    m_extent = e;
    m_section.extent = e;
    m_diagram = section_diagram(m_document->scene(), m_section, m_selected);
    update();
}

void SectionWidget::inspect(int ray) {
    m_inspected = ray;
    m_inspected_text.clear();
    if (ray >= 0) {
        const SectionRayReport report =
            section_ray_report(m_document->scene(), m_section.rays[size_t(ray)]);
        m_inspected_text = QString::fromStdString(format_section_ray_report(report));
    }
    emit ray_inspected(m_inspected_text);
    update();
}

bool SectionWidget::follow_rays(std::vector<SectionArm>& arms) const {
    bool moved = false;
    for (SectionArm& arm : arms) {
        if (arm.ray < 0) continue;
        for (const SectionRayPath& r : m_section.rays) {
            if (r.start != arm.ray || r.wavelength_nm != arm.nm) continue;
            const int segments = int(r.points.size()) - 1;
            const int k = arm.segment < 0 ? segments + arm.segment : arm.segment;
            if (k < 0 || k >= segments) break;
            arm.a = m_plane.of(r.points[size_t(k)]);
            arm.b = m_plane.of(r.points[size_t(k) + 1]);
            moved = true;
            break;
        }
    }
    return moved;
}

std::optional<double> SectionWidget::protractor_reading() const {
    if (m_arms.size() < 2) return std::nullopt;
    return protractor_degrees(m_arms[0], m_arms[1]);
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

int SectionWidget::ray_at(const QPointF& pixel) const {
    const DiagramPoint p = to_plane(pixel);
    double nearest = kSectionPickPixels / placement().scale;
    int found = -1;
    for (size_t r = 0; r < m_section.rays.size(); ++r) {
        const std::vector<Vec3>& points = m_section.rays[r].points;
        for (size_t i = 0; i + 1 < points.size(); ++i) {
            const double d =
                distance_to_segment(p, m_plane.of(points[i]), m_plane.of(points[i + 1]));
            if (d < nearest) nearest = d, found = int(r);
        }
    }
    return found;
}

std::optional<SectionArm> SectionWidget::arm_at(const QPointF& pixel) const {
    const DiagramPoint p = to_plane(pixel);
    double nearest = kSectionPickPixels / placement().scale;
    std::optional<SectionArm> arm;
    const auto consider = [&](const SectionArm& candidate) {
        const double d = distance_to_segment(p, candidate.a, candidate.b);
        if (d < nearest) nearest = d, arm = candidate;
    };
    for (const SectionRayPath& r : m_section.rays) {
        const int segments = int(r.points.size()) - 1;
        for (int i = 0; i < segments; ++i) {
            SectionArm candidate{m_plane.of(r.points[size_t(i)]),
                                 m_plane.of(r.points[size_t(i) + 1]), true};
            if (r.start >= 0) {  // later segments counted from the end: the last leg stays last
                candidate.ray = r.start;
                candidate.nm = r.wavelength_nm;
                candidate.segment = segments >= 2 && 2 * i >= segments ? i - segments : i;
            }
            consider(candidate);
        }
    }
    for (const SectionObject& o : m_section.objects) {
        for (const SectionCurve& c : o.curves) {
            for (size_t i = 0; i + 1 < c.points.size(); ++i)
                consider({c.points[i], c.points[i + 1], false});
        }
    }
    return arm;
}

void SectionWidget::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    const DiagramView view = placement();
    paint_diagram(painter, m_diagram, size(), view);
    if (m_inspected >= 0) {  // the clicked ray, traced over in a wide translucent band
        QPolygonF line;
        for (const Vec3& p : m_section.rays[size_t(m_inspected)].points)
            line << to_widget(m_plane.of(p));
        painter.setPen(QPen(QColor(255, 140, 0, 110), 7, Qt::SolidLine, Qt::RoundCap));
        painter.drawPolyline(line);
    }
    paint_measure(painter, view, measurements());
}

MeasureDrawing SectionWidget::measurements() const {
    const double pixel = 1 / placement().scale;
    MeasureDrawing all;
    const auto add = [&all](MeasureDrawing d) {
        all.paths.insert(all.paths.end(), d.paths.begin(), d.paths.end());
        all.labels.insert(all.labels.end(), d.labels.begin(), d.labels.end());
    };
    if (m_ruler_from && m_ruler_to) add(ruler_drawing(*m_ruler_from, *m_ruler_to, pixel));
    if (!m_arms.empty()) {
        add(protractor_drawing(m_arms[0],
                               m_arms.size() > 1 ? std::optional(m_arms[1]) : std::nullopt, pixel));
    }
    return all;
}

void SectionWidget::mousePressEvent(QMouseEvent* event) {
    m_press = m_last = event->position();
    m_dragged = false;
    m_drag_object = -1;
    m_panning = event->button() == Qt::MiddleButton;
    if (event->button() != Qt::LeftButton || m_panning) return;
    if (m_tool == SectionTool::Ruler) {
        m_ruler_from = m_ruler_to = to_plane(m_press);
        update();
        return;
    }
    if (m_tool == SectionTool::Protractor) {
        if (m_arms.size() == 2) m_arms.clear();
        if (const std::optional<SectionArm> arm = arm_at(m_press)) m_arms.push_back(*arm);
        if (const std::optional<double> degrees = protractor_reading())
            emit measured(tr("Protractor: %1°").arg(*degrees, 0, 'f', 2));
        update();
        return;
    }
    const int object = object_at(m_press);
    if (object < 0 || m_document->scene().objects[object].source < 0) {
        m_panning = true;  // empty paper: a drag pans, a click selects nothing or a ray
        return;
    }
    m_drag_view = fit_diagram_to(m_diagram, size());
    m_drag_object = object;
    m_pivot = section_centre(m_section, object);
    m_before = m_document->json();
}

void SectionWidget::mouseMoveEvent(QMouseEvent* event) {
    const QPointF at = event->position();
    if (!m_dragged && (at - m_press).manhattanLength() < kSectionDragPixels) return;
    if (m_panning) {
        m_dragged = true;
        const double scale = placement().scale;
        const double dz = (m_last.x() - at.x()) / scale, dy = (at.y() - m_last.y()) / scale;
        m_last = at;
        show_extent(
            {m_extent.a_min + dz, m_extent.a_max + dz, m_extent.b_min + dy, m_extent.b_max + dy});
        return;
    }
    if (m_tool == SectionTool::Ruler && m_ruler_from && (event->buttons() & Qt::LeftButton)) {
        m_ruler_to = to_plane(at);
        emit measured(tr("Ruler: %1").arg(ruler_text(*m_ruler_from, *m_ruler_to)));
        update();
        return;
    }
    if (m_drag_object < 0) return;
    m_dragged = true;
    drag_object_to(at, event->modifiers() & Qt::ShiftModifier);
}

void SectionWidget::drag_object_to(const QPointF& at, bool turn) {
    const DiagramPoint from = to_plane(m_press), to = to_plane(at);
    const int entry = m_document->scene().objects[m_drag_object].source;
    nlohmann::json edited = m_before;
    nlohmann::json& element = edited["objects"][size_t(entry)];
    const ObjectTypeEntry* kind = find_object_type(element.value("type", ""));
    if (!kind) return;
    if (turn && element_turns(kind->spec())) {
        // Turned about its centre by the angle the mouse swept around it (counter-clockwise
        // in the picture is positive about the plane's normal, u x v).
        const double angle = std::atan2(to.y - m_pivot.y, to.z - m_pivot.z) -
                             std::atan2(from.y - m_pivot.y, from.z - m_pivot.z);
        element =
            rotated_element(kind->spec(), element, m_plane.at(m_pivot), m_plane.normal(), angle);
    } else {
        const Vec3 offset = m_plane.u * (to.z - from.z) + m_plane.v * (to.y - from.y);
        element = moved_element(kind->spec(), element, offset);
    }
    if (!m_document->preview(edited)) emit edit_refused(tr("Cannot move the object there."));
}

void SectionWidget::mouseReleaseEvent(QMouseEvent* event) {
    const bool panned = m_panning && m_dragged;
    const bool clicked_paper = m_panning && !m_dragged && event->button() == Qt::LeftButton;
    m_panning = false;
    if (event->button() != Qt::LeftButton || panned || m_tool != SectionTool::Move) return;
    const int object = m_drag_object;
    m_drag_object = -1;
    if (clicked_paper) {
        // A ray under the click is inspected (the selection stays); else nothing is selected.
        const int ray = ray_at(event->position());
        if (ray >= 0) {
            inspect(ray);
        } else {
            inspect(-1);
            emit object_picked(-1);
        }
    } else if (m_dragged) {
        const std::string name = m_document->scene().objects[object].name;
        m_document->commit_preview(m_before, tr("Move %1").arg(QString::fromStdString(name)));
        m_dragged = false;
        update();  // placed by the widget's size again, not the press's
    } else {
        emit object_picked(object_at(event->position()));
    }
}

void SectionWidget::resizeEvent(QResizeEvent*) { show_extent(m_wanted); }

void SectionWidget::wheelEvent(QWheelEvent* event) {
    if (m_drag_object >= 0) return;
    const double factor = std::pow(0.85, event->angleDelta().y() / 120.0);
    const DiagramPoint at = to_plane(event->position());
    const auto scale = [&](double v, double centre) { return centre + (v - centre) * factor; };
    show_extent({scale(m_extent.a_min, at.z), scale(m_extent.a_max, at.z),
                 scale(m_extent.b_min, at.y), scale(m_extent.b_max, at.y)});
}

bool SectionWidget::export_svg(const QString& path, QString* error) const {
    RayDiagram drawing = m_diagram;  // with the ruler and protractor laid on it
    const MeasureDrawing measures = measurements();
    drawing.paths.insert(drawing.paths.end(), measures.paths.begin(), measures.paths.end());
    drawing.labels.insert(drawing.labels.end(), measures.labels.begin(), measures.labels.end());
    const std::string svg = ray_diagram_svg(drawing);
    QSaveFile out(path);
    if (out.open(QIODevice::WriteOnly) &&
        out.write(svg.data(), qint64(svg.size())) == qint64(svg.size()) && out.commit())
        return true;
    if (error) *error = tr("Cannot write %1: %2").arg(path, out.errorString());
    return false;
}

bool SectionWidget::export_png(const QString& path, QString* error) {
    QImage image(size(), QImage::Format_ARGB32_Premultiplied);
    render(&image);
    QSaveFile out(path);
    if (out.open(QIODevice::WriteOnly) && image.save(&out, "PNG") && out.commit()) return true;
    if (error) *error = tr("Cannot write %1: %2").arg(path, out.errorString());
    return false;
}

}  // namespace lenslab::gui
