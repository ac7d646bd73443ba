#include "viewport.h"

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>
#include <cmath>
#include <functional>
#include <limits>

#include "render/camera.h"
#include "scene_document.h"

namespace lenslab::gui {

namespace {

using nlohmann::json;

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

}  // namespace

Viewport::Viewport(SceneDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document) {
    setMinimumSize(320, 240);
    setMouseTracking(false);
    setFocusPolicy(Qt::StrongFocus);
    setToolTip(tr("Left drag: orbit. Right or middle drag: pan. Wheel: zoom. Click: select."));
}

void Viewport::set_image(const QImage& image) {
    m_image = image;
    update();
}

QRect Viewport::image_rect() const {
    const Scene& s = m_document->scene();
    QSize size(s.render.width, s.render.height);
    size.scale(this->size(), Qt::KeepAspectRatio);
    return QRect(QPoint((width() - size.width()) / 2, (height() - size.height()) / 2), size);
}

void Viewport::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), QColor(32, 32, 36));
    if (!m_image.isNull()) p.drawImage(image_rect(), m_image);
}

int Viewport::pick(const QPoint& pos) const {
    const QRect r = image_rect();
    if (!r.contains(pos)) return -1;
    const Scene& scene = m_document->scene();
    const Camera camera(scene.camera, scene.render.width, scene.render.height);
    const double px = (pos.x() - r.left() + 0.5) * scene.render.width / double(r.width());
    const double py = (pos.y() - r.top() + 0.5) * scene.render.height / double(r.height());
    SceneHit hit;
    if (!scene.intersect(camera.generate_ray(px, py), 0, std::numeric_limits<double>::infinity(),
                         hit))
        return -1;
    return scene.objects[hit.object]
        .source;  // the scene file's entry (a lens group's, for its elements)
}

void Viewport::mousePressEvent(QMouseEvent* event) {
    m_press = m_last = event->pos();
    m_button = event->button();
    m_dragged = false;
    m_before = m_document->json();
}

void Viewport::mouseMoveEvent(QMouseEvent* event) {
    if (m_button == Qt::NoButton) return;
    const QPoint delta = event->pos() - m_last;
    m_last = event->pos();
    if (!m_dragged && (event->pos() - m_press).manhattanLength() < 4) return;
    m_dragged = true;
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

void Viewport::mouseReleaseEvent(QMouseEvent* event) {
    if (!m_dragged) {
        if (event->button() == Qt::LeftButton) emit object_picked(pick(event->pos()));
    } else {
        m_document->commit_preview(m_before, tr("Move camera"));
    }
    m_button = Qt::NoButton;
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

}  // namespace lenslab::gui
