#include "analysis/real_ray.h"

#include <cmath>

#include "optics/refraction.h"

namespace lenslab {

std::vector<double> index_ratios(const OpticalSystem& system, double nm) {
    std::vector<double> ratios(system.surfaces.size());
    for (size_t i = 0; i < ratios.size(); ++i)
        ratios[i] = system.n_before(i, nm) / system.n_after(i, nm);
    return ratios;
}

RealRay trace_real_ray(const OpticalSystem& system, const Ray& ray, double nm, Rims rims) {
    return trace_real_ray(system, ray, index_ratios(system, nm), rims);
}

RealRay trace_real_ray(const OpticalSystem& system, const Ray& ray,
                       const std::vector<double>& ratios, Rims rims) {
    RealRay out;
    out.points.reserve(system.surfaces.size() + 1);
    out.points.push_back(ray.origin);
    Vec3 p = ray.origin;
    Vec3 d = ray.direction;
    for (size_t i = 0; i < system.surfaces.size(); ++i) {
        const SystemSurface& s = system.surfaces[i];
        // Into the surface's own frame: vertex at the origin, its +z along `orientation`.
        // Surfaces of revolution need no turn about the axis.
        const double o = s.orientation;
        const Ray local{{p.x, p.y, o * (p.z - s.z)}, {d.x, d.y, o * d.z}};
        double t;
        const SurfaceSpan& span = rims == Rims::Clip ? s.span : s.aim_span;
        if (!s.shape->intersect(local, span, 0.0, INFINITY, t)) {
            out.fate = RayFate::Missed;
            out.surface = static_cast<int>(i);
            out.direction = d;
            return out;
        }
        p = p + d * t;
        out.points.push_back(p);
        const Vec3 nl = s.shape->normal(local.at(t));
        Vec3 n{nl.x, nl.y, o * nl.z};
        if (dot(n, d) > 0) n = -n;  // facing the arriving ray
        const auto refracted = refract(d, n, ratios[i]);
        if (!refracted) {
            out.fate = RayFate::Reflected;
            out.surface = static_cast<int>(i);
            out.direction = d;
            return out;
        }
        d = *refracted;
    }
    out.direction = d;
    return out;
}

Vec3 at_plane(const Vec3& point, const Vec3& direction, double z_plane) {
    const double s = (z_plane - point.z) / direction.z;
    return {point.x + s * direction.x, point.y + s * direction.y, z_plane};
}

}  // namespace lenslab
