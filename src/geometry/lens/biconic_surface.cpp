#include "geometry/lens/biconic_surface.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "geometry/lens/conic_surface.h"

namespace lenslab {

BiconicSurface::BiconicSurface(double radius_x, double radius_y, double k_x, double k_y)
    : m_radius_x(radius_x),
      m_radius_y(radius_y),
      m_cx(radius_x == 0 ? 0.0 : 1.0 / radius_x),
      m_cy(radius_y == 0 ? 0.0 : 1.0 / radius_y),
      m_kx(k_x),
      m_ky(k_y) {}

double BiconicSurface::sag_and_gradient(double x, double y, double& dz_dx, double& dz_dy) const {
    const double ax = (1 + m_kx) * m_cx * m_cx, ay = (1 + m_ky) * m_cy * m_cy;
    const double q = 1 - ax * x * x - ay * y * y;
    if (q < 0) {
        dz_dx = dz_dy = std::numeric_limits<double>::quiet_NaN();
        return dz_dx;
    }
    const double root = std::sqrt(q), d = 1 + root;
    const double n = m_cx * x * x + m_cy * y * y;
    // z = n / d with dd = dq / (2 root), dq/dx = -2 ax x.
    const double z = n / d;
    const double droot_dx = root > 0 ? -ax * x / root : 0.0;
    const double droot_dy = root > 0 ? -ay * y / root : 0.0;
    dz_dx = (2 * m_cx * x - z * droot_dx) / d;
    dz_dy = (2 * m_cy * y - z * droot_dy) / d;
    return z;
}

double BiconicSurface::max_semi_diameter() const {
    return std::min(ConicSurface::conic_max_semi_diameter(m_cx, m_kx),
                    ConicSurface::conic_max_semi_diameter(m_cy, m_ky));
}

std::string BiconicSurface::describe() const {
    std::ostringstream s;
    s << "biconic Rx=" << m_radius_x << " Ry=" << m_radius_y << " kx=" << m_kx << " ky=" << m_ky;
    return s.str();
}

std::string BiconicSurface::why_undefined(double x, double y) const {
    const double q = 1 - (1 + m_kx) * m_cx * m_cx * x * x - (1 + m_ky) * m_cy * m_cy * y * y;
    return q < 0 ? "sqrt of a negative number" : "";
}

}  // namespace lenslab
