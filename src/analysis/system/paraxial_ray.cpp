#include "analysis/system/paraxial_ray.h"

#include "analysis/system/grin_gap.h"

namespace lenslab {

double ParaxialRay::height_after(const OpticalSystem& system, double z) const {
    return last().y + last().u_after * (z - system.last_vertex());
}

ParaxialRay trace_paraxial_ray(const OpticalSystem& system, double nm, double y0, double u0) {
    ParaxialRay ray;
    ray.y0 = y0;
    ray.u0 = u0;
    double y = y0, u = u0;
    for (size_t i = 0; i < system.surfaces.size(); ++i) {
        const SystemSurface& s = system.surfaces[i];
        if (i == 0) {
            y += u * s.z;  // object space
        } else {
            const GapTransfer g = gap_transfer(system, i - 1, nm);
            const double nu = ray.surfaces.back().n_after * u;
            const double y_next = g.a * y + g.b * nu;
            u = (g.c * y + g.d * nu) / system.n_before(i, nm);
            y = y_next;
        }
        ParaxialRaySurface at;
        at.y = y;
        at.u = u;
        at.n = system.n_before(i, nm);
        at.n_after = system.n_after(i, nm);
        at.u_after = (at.n * u - y * s.curvature * (at.n_after - at.n)) / at.n_after;
        u = at.u_after;
        ray.surfaces.push_back(at);
    }
    return ray;
}

ParaxialRay combine_rays(double a, const ParaxialRay& r1, double b, const ParaxialRay& r2) {
    ParaxialRay r = r1;
    r.y0 = a * r1.y0 + b * r2.y0;
    r.u0 = a * r1.u0 + b * r2.u0;
    for (size_t i = 0; i < r.surfaces.size(); ++i) {
        const ParaxialRaySurface& p = r1.surfaces[i];
        const ParaxialRaySurface& q = r2.surfaces[i];
        r.surfaces[i].y = a * p.y + b * q.y;
        r.surfaces[i].u = a * p.u + b * q.u;
        r.surfaces[i].u_after = a * p.u_after + b * q.u_after;
    }
    return r;
}

}  // namespace lenslab
