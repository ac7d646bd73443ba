#include "viewport.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>
#include <cmath>
#include <functional>
#include <limits>

#include "json_pointer.h"
#include "placement.h"
#include "scene/light_spec.h"
#include "scene/object_types.h"
#include "scene/param_spec.h"
#include "scene_document.h"

namespace lenslab::gui {

namespace {

using nlohmann::json;

// The selection's outline: orange, as Blender's.
const QColor kOutlineColour(255, 150, 30);

Vec3 to_vec(const json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}; }
json to_json(const Vec3& v) { return json::array({v.x, v.y, v.z}); }

// Rotates v about the unit axis k by angle a (Rodrigues' formula).
Vec3 rotate(const Vec3& v, const Vec3& k, double a) {
    return v * std::cos(a) + cross(k, v) * std::sin(a) + k * (dot(k, v) * (1 - std::cos(a)));
}

// The camera rewritten as position + look_at after an orbit, pan or zoom. The orbit centre
// is look_at, or 5 units ahead when the file gives a direction.
json moved_camera(const json& camera, const std::function<void(Vec3&, Vec3&)>& move) {
    Vec3 position = to_vec(camera["position"]);
    Vec3 target = camera.contains("look_at")
                      ? to_vec(camera["look_at"])
                      : position + normalize(to_vec(camera["direction"])) * 5.0;
    move(position, target);
    json out = camera;
    out.erase("direction");
    out["position"] = to_json(position);
    out["look_at"] = to_json(target);
    return out;
}

// The declaration of an entry of `list` ("objects", "lights"), or null.
const ElementSpec* viewport_element_spec(const std::string& list, const json& element) {
    const std::string type = element.value("type", "");
    if (list == "lights") return find_light_spec(type);
    const ObjectTypeEntry* kind = find_object_type(type);
    return kind ? &kind->spec() : nullptr;
}

Vec3 unit_axis(int axis) {
    return {axis == 0 ? 1.0 : 0.0, axis == 1 ? 1.0 : 0.0, axis == 2 ? 1.0 : 0.0};
}

}  // namespace

Viewport::Viewport(SceneDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document) {
    setObjectName("viewport");
    setMinimumSize(200, 100);
    setMouseTracking(false);
    setFocusPolicy(Qt::StrongFocus);
    setToolTip(
        tr("Left drag: orbit. Right or middle drag: pan. Wheel: zoom. Click: select. Drag an "
           "arrow to move the selection along it, a ring to turn it (Ctrl: in steps)."));
    connect(m_document, &SceneDocument::changed, this, [this] {
        m_outline_stale = true;
        update();
    });
}

void Viewport::set_image(const QImage& image) {
    m_image = image;
    update();
}

void Viewport::show_pointer(const QString& pointer) {
    m_pointer = pointer;
    if (m_placing >= 0 && pointer != join_pointer("/objects", qsizetype(m_placing)))
        arm_placement(-1);
    m_outline_stale = true;
    update();
}

void Viewport::arm_placement(int object) {
    m_placing = object;
    if (object >= 0)
        setCursor(Qt::CrossCursor);
    else
        unsetCursor();
}

QRect Viewport::image_rect() const {
    const Scene& s = m_document->scene();
    QSize size(s.render.width, s.render.height);
    size.scale(this->size(), Qt::KeepAspectRatio);
    return QRect(QPoint((width() - size.width()) / 2, (height() - size.height()) / 2), size);
}

ViewCamera Viewport::view_camera() const {
    const Scene& s = m_document->scene();
    return ViewCamera(s.camera, s.render.width, s.render.height, QRectF(image_rect()));
}

std::optional<std::pair<std::string, int>> Viewport::selected_entry() const {
    const QStringList tokens = split_pointer(m_pointer);  // {"objects", "3", ...}
    if (tokens.size() < 2 || (tokens[0] != "objects" && tokens[0] != "lights")) return std::nullopt;
    bool ok = false;
    const int index = tokens[1].toInt(&ok);
    const std::string list = tokens[0].toStdString();
    const json& doc = m_document->json();
    if (!ok || index < 0 || !doc.contains(list) || size_t(index) >= doc[list].size())
        return std::nullopt;
    return std::pair{list, index};
}

std::optional<Vec3> Viewport::selection_pivot() const {
    const auto entry = selected_entry();
    if (!entry) return std::nullopt;
    if (entry->first == "objects") {
        const Aabb box = entry_bounds(m_document->scene(), entry->second);
        if (box.empty()) return std::nullopt;
        return box.centre();
    }
    for (const LightIcon& icon : light_icons()) {
        if (icon.index == entry->second) return icon.position;
    }
    return std::nullopt;
}

std::optional<TransformHandles> Viewport::handles() const {
    const auto entry = selected_entry();
    const std::optional<Vec3> pivot = selection_pivot();
    if (!entry || !pivot || m_placing >= 0) return std::nullopt;
    const ElementSpec* spec =
        viewport_element_spec(entry->first, m_document->json()[entry->first][entry->second]);
    if (!spec) return std::nullopt;
    return TransformHandles(view_camera(), *pivot, element_turns(*spec));
}

const SelectionOutline& Viewport::outline() {
    if (m_outline_stale) {
        m_outline = {};
        const auto entry = selected_entry();
        if (entry && entry->first == "objects")
            m_outline = selection_outline(m_document->scene(), entry->second, view_camera(),
                                          kOutlineColour);
        m_outline_stale = false;
    }
    return m_outline;
}

std::vector<LightIcon> Viewport::light_icons() const {
    return gui::light_icons(m_document->json(), view_camera());
}

void Viewport::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), QColor(32, 32, 36));
    if (!m_image.isNull()) p.drawImage(image_rect(), m_image);
    const SelectionOutline& line = outline();
    if (!line.image.isNull()) p.drawImage(line.where, line.image);
    const auto entry = selected_entry();
    for (const LightIcon& icon : light_icons())
        paint_light_icon(p, icon, entry && entry->first == "lights" && entry->second == icon.index);
    if (const std::optional<TransformHandles> h = handles()) h->paint(p, m_active);
}

int Viewport::pick(const QPoint& pos) const {
    if (!image_rect().contains(pos)) return -1;
    const Scene& scene = m_document->scene();
    SceneHit hit;
    if (!scene.intersect(view_camera().ray(QPointF(pos) + QPointF(0.5, 0.5)), 0,
                         std::numeric_limits<double>::infinity(), hit))
        return -1;
    return scene.objects[hit.object]
        .source;  // the scene file's entry (a lens group's, for its elements)
}

void Viewport::mousePressEvent(QMouseEvent* event) {
    m_press = m_last = event->pos();
    m_button = event->button();
    m_dragged = false;
    m_before = m_document->json();
    m_active = {};
    m_drag_handles.reset();
    if (m_button != Qt::LeftButton) return;
    if (const std::optional<TransformHandles> h = handles()) {
        m_active = h->at(event->position());
        if (m_active.kind != HandleKind::None) {
            m_drag_handles = h;
            m_drag_pivot = *selection_pivot();
            m_turned = 0;
            update();
        }
    }
}

void Viewport::mouseMoveEvent(QMouseEvent* event) {
    if (m_button == Qt::NoButton) return;
    const QPoint delta = event->pos() - m_last;
    if (!m_dragged && (event->pos() - m_press).manhattanLength() < 4) return;
    m_dragged = true;
    if (m_drag_handles)
        drag_handle(event->position(), event->modifiers() & Qt::ControlModifier);
    else
        drag_camera(delta);
    m_last = event->pos();
}

void Viewport::drag_camera(const QPoint& delta) {
    const Vec3 up = m_document->scene().camera.up;
    const double dx = delta.x(), dy = delta.y();
    json edited = m_document->json();
    if (m_button == Qt::LeftButton) {
        edited["camera"] = moved_camera(edited["camera"], [&](Vec3& pos, Vec3& target) {
            Vec3 offset = pos - target;
            offset = rotate(offset, normalize(up), -dx * 0.01);
            const Vec3 right = normalize(cross(offset, up));
            const Vec3 pitched = rotate(offset, right, dy * 0.01);
            // Stop short of the poles, where "up" would flip.
            if (std::abs(dot(normalize(pitched), normalize(up))) < 0.98) offset = pitched;
            pos = target + offset;
        });
    } else {
        edited["camera"] = moved_camera(edited["camera"], [&](Vec3& pos, Vec3& target) {
            const Vec3 forward = target - pos;
            const Vec3 right = normalize(cross(forward, up));
            const Vec3 cam_up = normalize(cross(right, forward));
            const double scale = length(forward) * 0.002;
            const Vec3 shift = (right * -dx + cam_up * dy) * scale;
            pos += shift;
            target += shift;
        });
    }
    m_document->preview(edited);
}

void Viewport::drag_handle(const QPointF& at, bool snap) {
    const auto entry = selected_entry();
    if (!entry) return;
    json edited = m_before;
    json& element = edited[entry->first][size_t(entry->second)];
    const ElementSpec* spec = viewport_element_spec(entry->first, element);
    if (!spec) return;
    const int axis = m_active.axis;
    if (m_active.kind == HandleKind::Move) {
        double distance = m_drag_handles->move_distance(axis, QPointF(m_press), at);
        if (snap)
            distance =
                std::round(distance / m_drag_handles->move_snap()) * m_drag_handles->move_snap();
        element = moved_element(*spec, element, unit_axis(axis) * distance);
    } else {
        m_turned += m_drag_handles->rotate_angle(axis, QPointF(m_last), at);
        const double step = TransformHandles::rotate_snap();
        const double angle = snap ? std::round(m_turned / step) * step : m_turned;
        element = rotated_element(*spec, element, m_drag_pivot, unit_axis(axis), angle);
    }
    if (!m_document->preview(edited)) emit edit_refused(tr("Cannot move the selection there."));
}

void Viewport::place_armed(const QPoint& pos) {
    const int entry = m_placing;
    arm_placement(-1);
    json edited = m_document->json();
    if (!edited.contains("objects") || size_t(entry) >= edited["objects"].size()) return;
    json& element = edited["objects"][size_t(entry)];
    const ElementSpec* spec = viewport_element_spec("objects", element);
    const Scene& scene = m_document->scene();
    const Aabb box = entry_bounds(scene, entry);
    if (!spec || box.empty() || !image_rect().contains(pos)) return;
    const Ray ray = view_camera().ray(QPointF(pos) + QPointF(0.5, 0.5));
    // Nothing there: at the depth it is now, under the cursor.
    const Vec3 offset = resting_offset(scene, box, ray, entry)
                            .value_or(ray.at(length(box.centre() - ray.origin)) - box.centre());
    element = moved_element(*spec, element, offset);
    QString error;
    if (!m_document->apply(
            edited, tr("Place %1").arg(QString::fromStdString(element.value("name", "object"))),
            &error))
        emit edit_refused(error);
}

void Viewport::mouseReleaseEvent(QMouseEvent* event) {
    const bool dragged = m_dragged;
    const bool handle_drag = m_drag_handles.has_value();
    const HandleKind kind = m_active.kind;
    m_button = Qt::NoButton;
    m_dragged = false;
    m_drag_handles.reset();
    m_active = {};
    if (!dragged) {
        if (event->button() != Qt::LeftButton) return;
        if (m_placing >= 0) {
            place_armed(event->pos());
        } else if (handle_drag) {
            update();  // a click on a handle changes nothing
        } else if (const int light = light_icon_at(light_icons(), event->position()); light >= 0) {
            emit light_picked(light);
        } else {
            emit object_picked(pick(event->pos()));
        }
        return;
    }
    if (const auto entry = selected_entry(); handle_drag && entry) {
        const json& element = m_document->json()[entry->first][size_t(entry->second)];
        const QString name = QString::fromStdString(
            element.value("name", entry->first == "lights" ? "light" : "object"));
        m_document->commit_preview(m_before, kind == HandleKind::Rotate ? tr("Rotate %1").arg(name)
                                                                        : tr("Move %1").arg(name));
    } else if (!handle_drag) {
        m_document->commit_preview(m_before, tr("Move camera"));
    }
    update();
    emit interaction_finished();
}

void Viewport::wheelEvent(QWheelEvent* event) {
    const double steps = event->angleDelta().y() / 120.0;
    json edited = m_document->json();
    edited["camera"] = moved_camera(edited["camera"], [&](Vec3& pos, Vec3& target) {
        pos = target + (pos - target) * std::pow(0.9, steps);
    });
    QString error;
    if (!m_document->apply(edited, tr("Zoom camera"), &error)) emit edit_refused(error);
}

void Viewport::keyPressEvent(QKeyEvent* event) {
    if (event->key() == Qt::Key_Escape && m_placing >= 0) {
        arm_placement(-1);
        return;
    }
    QWidget::keyPressEvent(event);
}

void Viewport::resizeEvent(QResizeEvent* event) {
    m_outline_stale = true;
    QWidget::resizeEvent(event);
}

}  // namespace lenslab::gui
