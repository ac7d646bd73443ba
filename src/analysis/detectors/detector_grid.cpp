#include "analysis/detectors/detector_grid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "geometry/shape.h"

namespace lenslab {

namespace {

using Point2 = std::array<double, 2>;

// Sutherland-Hodgman: keeps the part of `poly` where s * (p[axis] - at) <= 0.
std::vector<Point2> clip(const std::vector<Point2>& poly, int axis, double at, double s) {
    std::vector<Point2> out;
    for (size_t i = 0; i < poly.size(); ++i) {
        const Point2& a = poly[i];
        const Point2& b = poly[(i + 1) % poly.size()];
        const double da = s * (a[axis] - at), db = s * (b[axis] - at);
        if (da <= 0) out.push_back(a);
        if ((da < 0 && db > 0) || (da > 0 && db < 0)) {
            const double f = da / (da - db);
            out.push_back({a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])});
        }
    }
    return out;
}

double polygon_area(const std::vector<Point2>& p) {
    double twice = 0;
    for (size_t i = 0; i < p.size(); ++i) {
        const Point2& a = p[i];
        const Point2& b = p[(i + 1) % p.size()];
        twice += a[0] * b[1] - b[0] * a[1];
    }
    return 0.5 * std::abs(twice);
}

}  // namespace

double rectangle_disc_overlap(double u0, double u1, double v0, double v1, double r) {
    // Wholly inside (every corner within r) or wholly outside (nearest point beyond r).
    const double far_u = std::max(std::abs(u0), std::abs(u1)),
                 far_v = std::max(std::abs(v0), std::abs(v1));
    if (far_u * far_u + far_v * far_v <= r * r) return (u1 - u0) * (v1 - v0);
    const double near_u = (u0 <= 0 && u1 >= 0) ? 0 : std::min(std::abs(u0), std::abs(u1));
    const double near_v = (v0 <= 0 && v1 >= 0) ? 0 : std::min(std::abs(v0), std::abs(v1));
    if (near_u * near_u + near_v * near_v >= r * r) return 0;
    // Integrate the chord's overlap with [v0, v1] across u = r sin(phi) (midpoint rule in
    // phi, where the integrand is smooth up to the rim).
    const double a = std::asin(std::max(u0, -r) / r), b = std::asin(std::min(u1, r) / r);
    constexpr int kSteps = 1024;
    const double dphi = (b - a) / kSteps;
    double area = 0;
    for (int i = 0; i < kSteps; ++i) {
        const double phi = a + (i + 0.5) * dphi;
        const double h = r * std::cos(phi);
        area += std::max(0.0, std::min(v1, h) - std::max(v0, -h)) * h;  // du = r cos(phi) dphi
    }
    return area * dphi;
}

double rectangle_triangle_overlap(double u0, double u1, double v0, double v1,
                                  const double (&tri)[3][2]) {
    std::vector<Point2> p{{tri[0][0], tri[0][1]}, {tri[1][0], tri[1][1]}, {tri[2][0], tri[2][1]}};
    p = clip(p, 0, u0, -1);
    p = clip(p, 0, u1, +1);
    p = clip(p, 1, v0, -1);
    p = clip(p, 1, v1, +1);
    return p.size() < 3 ? 0.0 : polygon_area(p);
}

DetectorGrid DetectorGrid::for_object(const SceneObject& object) {
    if (!object.detector) throw std::invalid_argument(object.name + " is not a detector");
    const DetectorSettings& d = *object.detector;
    DetectorGrid g;
    const std::optional<FlatPatch> patch = object.shape->flat_patch();
    if (!patch) {
        throw std::invalid_argument(object.name +
                                    ": only a triangle, disc or rectangle can be a detector");
    }
    g.m_frame = patch->frame;
    g.m_u0 = patch->u0;
    g.m_u1 = patch->u1;
    g.m_v0 = patch->v0;
    g.m_v1 = patch->v1;
    // A triangle's corners in (u, v), for the cells it covers in part.
    double tri[3][2] = {};
    const bool is_triangle = patch->corners.size() == 3;
    for (size_t i = 0; is_triangle && i < 3; ++i) {
        tri[i][0] = g.m_frame.u_of(patch->corners[i]);
        tri[i][1] = g.m_frame.v_of(patch->corners[i]);
    }
    detector_cells(d, g.m_u1 - g.m_u0, g.m_v1 - g.m_v0, g.m_nu, g.m_nv);
    g.m_area.resize(static_cast<size_t>(g.cell_count()));
    for (int c = 0; c < g.cell_count(); ++c) {
        const double a0 = g.m_u0 + (c % g.m_nu) * g.cell_width(), a1 = a0 + g.cell_width();
        const double b0 = g.m_v0 + (c / g.m_nu) * g.cell_height(), b1 = b0 + g.cell_height();
        if (patch->is_disc()) {
            g.m_area[static_cast<size_t>(c)] = rectangle_disc_overlap(a0, a1, b0, b1, g.m_u1);
        } else if (is_triangle) {
            g.m_area[static_cast<size_t>(c)] = rectangle_triangle_overlap(a0, a1, b0, b1, tri);
        } else {
            g.m_area[static_cast<size_t>(c)] = (a1 - a0) * (b1 - b0);
        }
    }
    return g;
}

int DetectorGrid::cell_at(double u, double v) const {
    // A point on the rim may round to just outside the box: it belongs to the edge cell.
    const int iu = std::clamp(static_cast<int>(std::floor((u - m_u0) / cell_width())), 0, m_nu - 1);
    const int iv =
        std::clamp(static_cast<int>(std::floor((v - m_v0) / cell_height())), 0, m_nv - 1);
    return iv * m_nu + iu;
}

double DetectorGrid::surface_area() const {
    double sum = 0;
    for (double a : m_area) sum += a;
    return sum;
}

}  // namespace lenslab
