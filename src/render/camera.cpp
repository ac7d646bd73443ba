#include "render/camera.h"

#include <cmath>
#include <numbers>

namespace lenslab {

Camera::Camera(const CameraSettings& s, int width, int height)
    : m_origin(s.position), m_forward(normalize(s.direction)), m_width(width), m_height(height) {
    m_right = normalize(cross(m_forward, s.up));
    m_up = cross(m_right, m_forward);
    m_half_height = std::tan(0.5 * s.fov_deg * std::numbers::pi / 180.0);
    m_half_width = m_half_height * static_cast<double>(width) / height;
}

Ray Camera::generate_ray(double px, double py) const {
    const double sx = (2.0 * px / m_width - 1.0) * m_half_width;
    const double sy = (1.0 - 2.0 * py / m_height) * m_half_height;
    return {m_origin, normalize(m_forward + m_right * sx + m_up * sy)};
}

bool Camera::project(const Vec3& p, double& px, double& py) const {
    const Vec3 d = p - m_origin;
    const double depth = dot(d, m_forward);
    if (depth <= 1e-12) return false;
    const double sx = dot(d, m_right) / depth, sy = dot(d, m_up) / depth;
    px = (sx / m_half_width + 1.0) * 0.5 * m_width;
    py = (1.0 - sy / m_half_height) * 0.5 * m_height;
    return true;
}

}  // namespace lenslab
