#include "analysis/system/real_ray.h"

#include <cmath>

#include "analysis/system/grin_gap.h"
#include "optics/refraction.h"

namespace lenslab {

IndexRatios index_ratios(const OpticalSystem& system, double nm) {
    IndexRatios out{nm, std::vector<double>(system.surfaces.size())};
    for (size_t i = 0; i < out.ratios.size(); ++i) {
        const bool graded = grin_gap(system, i) || (i > 0 && grin_gap(system, i - 1));
        // A mirror's entry is unused (it reflects); the signs of travel cancel in the rest.
        out.ratios[i] = graded ? NAN : system.n_before(i, nm) / system.n_after(i, nm);
    }
    return out;
}

RealRay trace_real_ray(const OpticalSystem& system, const Ray& ray, double nm, Rims rims,
                       std::vector<Vec3>* path) {
    return trace_real_ray(system, ray, index_ratios(system, nm), rims, path);
}

RealRay trace_real_ray(const OpticalSystem& system, const Ray& ray, const IndexRatios& indices,
                       Rims rims, std::vector<Vec3>* path) {
    RealRay out;
    trace_real_ray_into(out, system, ray, indices, rims, path);
    return out;
}

void trace_real_ray_into(RealRay& out, const OpticalSystem& system, const Ray& ray,
                         const IndexRatios& indices, Rims rims, std::vector<Vec3>* path) {
    const double nm = indices.wavelength_nm;
    out.fate = RayFate::Passed;
    out.surface = -1;
    out.points.clear();
    out.points.reserve(system.surfaces.size() + 1);
    out.points.push_back(ray.origin);
    if (path) path->assign(1, ray.origin);
    Vec3 p = ray.origin;
    Vec3 d = ray.direction;
    bool on_surface = false;  // brought to surface i through a gradient index
    for (size_t i = 0; i < system.surfaces.size(); ++i) {
        const SystemSurface& s = system.surfaces[i];
        const Ray local = s.to_local(p, d);
        double t = 0;
        const SurfaceSpan& span = rims == Rims::Clip ? s.span : s.aim_span;
        if (!on_surface && !s.shape->intersect(local, span, 0.0, INFINITY, t)) {
            out.fate = RayFate::Missed;
            out.surface = static_cast<int>(i);
            out.direction = d;
            return;
        }
        p = p + d * t;
        out.points.push_back(p);
        if (path && !on_surface) path->push_back(p);
        if (rims == Rims::Clip && s.in_hole(p)) {
            out.fate = RayFate::Missed;  // through a mirror's central hole
            out.surface = static_cast<int>(i);
            out.direction = d;
            return;
        }
        Vec3 n = s.to_system(s.shape->normal(local.at(t)));
        if (dot(n, d) > 0) n = -n;  // facing the arriving ray
        if (s.mirror) {
            d = reflect(d, n);
            continue;
        }
        // Next to a gradient index, the indices where the ray meets the surface.
        double ratio = indices.ratios[i];
        if (std::isnan(ratio))
            ratio =
                system.index_at(s.element_before, p, nm) / system.index_at(s.element_after, p, nm);
        const auto refracted = refract(d, n, ratio);
        if (!refracted) {
            out.fate = RayFate::Reflected;
            out.surface = static_cast<int>(i);
            out.direction = d;
            return;
        }
        d = *refracted;
        on_surface = grin_gap(system, i);
        if (on_surface) {
            const GrinTransit transit = trace_grin_gap(system, i, p, d, nm, path);
            if (!transit.arrived) {  // out through the rim: the lens edge stops it
                out.fate = RayFate::Missed;
                out.surface = static_cast<int>(i + 1);
                out.direction = d;
                return;
            }
            p = transit.point;
            d = transit.direction;
        }
    }
    out.direction = d;
}

Vec3 at_plane(const Vec3& point, const Vec3& direction, double z_plane) {
    const double s = (z_plane - point.z) / direction.z;
    return {point.x + s * direction.x, point.y + s * direction.y, z_plane};
}

}  // namespace lenslab
