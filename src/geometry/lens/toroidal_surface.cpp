#include "geometry/lens/toroidal_surface.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "geometry/lens/conic_surface.h"

namespace lenslab {

ToroidalSurface::ToroidalSurface(double radius, double k, std::vector<double> coefficients,
                                 double radius_of_rotation)
    : m_radius(radius),
      m_c(radius == 0 ? 0.0 : 1.0 / radius),
      m_k(k),
      m_coefficients(std::move(coefficients)),
      m_rotation(radius_of_rotation) {
    if (m_coefficients.size() > kMaxCoefficients) {
        throw std::invalid_argument("ToroidalSurface: at most 7 coefficients (A4 .. A16)");
    }
}

double ToroidalSurface::curve(double y, double& slope) const {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (1.0 - (1.0 + m_k) * m_c * m_c * y * y < 0) {
        slope = nan;
        return nan;
    }
    // Horner in y^2 for the terms and their slopes (d/dy A_{2i} y^{2i} = 2i A_{2i} y^{2i-1}).
    const double y2 = y * y;
    double poly = 0.0, dpoly = 0.0;
    for (size_t i = m_coefficients.size(); i-- > 0;) {
        poly = poly * y2 + m_coefficients[i];
        dpoly = dpoly * y2 + double(2 * (i + 2)) * m_coefficients[i];
    }
    slope = ConicSurface::conic_slope(m_c, m_k, y) + dpoly * y2 * y;
    return ConicSurface::conic_sag(m_c, m_k, y) + poly * y2 * y2;
}

double ToroidalSurface::sag_and_gradient(double x, double y, double& dz_dx, double& dz_dy) const {
    double slope;
    const double zy = curve(y, slope);
    if (m_rotation == 0) {  // swept straight along x
        dz_dx = 0;
        dz_dy = slope;
        return zy;
    }
    const double rho = m_rotation - zy;  // distance from the axis of rotation
    const double q = rho * rho - x * x;
    if (!(q >= 0)) {
        dz_dx = dz_dy = std::numeric_limits<double>::quiet_NaN();
        return dz_dx;
    }
    const double root = std::sqrt(q), side = m_rotation > 0 ? 1.0 : -1.0;
    dz_dx = root > 0 ? side * x / root : std::numeric_limits<double>::infinity();
    dz_dy = root > 0 ? side * rho * slope / root : std::numeric_limits<double>::infinity();
    return m_rotation - side * root;
}

double ToroidalSurface::max_semi_diameter() const {
    const double along_y = ConicSurface::conic_max_semi_diameter(m_c, m_k);
    return m_rotation == 0 ? along_y : std::min(along_y, std::abs(m_rotation));
}

std::string ToroidalSurface::describe() const {
    std::ostringstream s;
    s << "toroidal R=" << m_radius << " k=" << m_k;
    for (size_t i = 0; i < m_coefficients.size(); ++i) {
        s << " A" << 2 * (i + 2) << "=" << m_coefficients[i];
    }
    s << " rotation R=" << m_rotation;
    return s.str();
}

std::string ToroidalSurface::why_undefined(double x, double y) const {
    double dx, dy;
    return std::isnan(sag_and_gradient(x, y, dx, dy)) ? "sqrt of a negative number" : "";
}

}  // namespace lenslab
