#include "view_camera.h"

#include <cmath>
#include <numbers>

namespace lenslab::gui {

ViewCamera::ViewCamera(const CameraSettings& settings, int film_width, int film_height,
                       const QRectF& image)
    : m_settings(settings),
      m_camera(settings, film_width, film_height),
      m_width(film_width),
      m_height(film_height),
      m_image(image) {}

Ray ViewCamera::ray(const QPointF& widget) const {
    const double px = (widget.x() - m_image.left()) * m_width / m_image.width();
    const double py = (widget.y() - m_image.top()) * m_height / m_image.height();
    return m_camera.generate_ray(px, py);
}

std::optional<QPointF> ViewCamera::project(const Vec3& p) const {
    double px = 0, py = 0;
    if (!m_camera.project(p, px, py)) return std::nullopt;
    return QPointF(m_image.left() + px * m_image.width() / m_width,
                   m_image.top() + py * m_image.height() / m_height);
}

double ViewCamera::units_per_pixel(const Vec3& p) const {
    const double depth = std::max(dot(p - eye(), normalize(m_settings.direction)), 1e-9);
    const double half_height = std::tan(0.5 * m_settings.fov_deg * std::numbers::pi / 180.0);
    return 2 * depth * half_height / m_image.height();
}

}  // namespace lenslab::gui
