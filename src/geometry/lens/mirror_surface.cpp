#include "geometry/lens/mirror_surface.h"

#include <cmath>

namespace lenslab {

namespace {

// w along the axis, u along x_axis made perpendicular to it (else Duff et al.'s choice),
// v = w x u: the frame a lens takes (lens_solid.cpp), so a formula in x and y means the same.
Frame mirror_frame(const MirrorPrescription& p) {
    const Vec3 x = p.x_axis - p.axis * dot(p.x_axis, p.axis);
    if (!(length(x) > 1e-12)) return Frame::from_axis(p.axis);
    const Vec3 u = normalize(x);
    return {u, cross(p.axis, u), p.axis};
}

}  // namespace

MirrorSurface::MirrorSurface(MirrorPrescription p) : m_p(std::move(p)), m_frame(mirror_frame(m_p)) {
    const double a = 0.5 * m_p.diameter;
    m_span = measure_span(*m_p.surface, a);
    // The cylinder r <= a between the sag's extremes, its corners in the scene.
    for (const double x : {-a, a}) {
        for (const double y : {-a, a}) {
            for (const double z : {m_span.z_min, m_span.z_max})
                m_bounds.expand(m_p.vertex + m_frame.to_world({x, y, z}));
        }
    }
}

Vec3 MirrorSurface::point_at(double x, double y) const {
    return m_p.vertex + m_frame.to_world({x, y, m_p.surface->sag_xy(x, y)});
}

void MirrorSurface::for_each_facet(const FacetVisitor& visit) const {
    constexpr int kRings = 48, kSectors = 96;
    const double inner = 0.5 * m_p.hole_diameter, outer = 0.5 * m_p.diameter;
    const auto at = [&](int i, int j) {
        const double r = inner + (outer - inner) * i / kRings;
        const double phi = 2.0 * M_PI * j / kSectors;
        return point_at(r * std::cos(phi), r * std::sin(phi));
    };
    for (int i = 0; i < kRings; ++i) {
        for (int j = 0; j < kSectors; ++j) {
            const Vec3 quad[4] = {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
            visit(quad, 4);
        }
    }
}

bool MirrorSurface::intersect(const Ray& ray, double t_min, double t_max, SurfaceHit& hit) const {
    const Ray local{m_frame.to_local(ray.origin - m_p.vertex), m_frame.to_local(ray.direction)};
    const double hole = 0.5 * m_p.hole_diameter;
    // A ray through the hole may meet the surface again beyond it (a steep mirror seen from
    // the side): look once more past the first crossing.
    for (int attempt = 0; attempt < 2; ++attempt) {
        double t = 0;
        if (!m_p.surface->intersect(local, m_span, t_min, t_max, t)) return false;
        const Vec3 p = local.at(t);
        if (hole > 0 && p.x * p.x + p.y * p.y < hole * hole) {
            t_min = t;
            continue;
        }
        hit.t = t;
        hit.point = ray.at(t);
        hit.normal = m_frame.to_world(m_p.surface->normal(p));
        return true;
    }
    return false;
}

}  // namespace lenslab
