#include "analysis/system/grin_gap.h"

#include <cmath>

#include "scene/grin_ray.h"

namespace lenslab {

bool grin_gap(const OpticalSystem& system, size_t i) {
    const int e = system.surfaces[i].element_after;
    return e >= 0 && i + 1 < system.surfaces.size() && system.elements[e].grin != nullptr;
}

GapTransfer gap_transfer(const OpticalSystem& system, size_t i, double nm) {
    const double t = system.surfaces[i + 1].z - system.surfaces[i].z;
    const double n1 = system.n_after(i, nm);
    if (!grin_gap(system, i)) return {1, t / n1, 0, 1};
    const GrinProfile& g = *system.elements[system.surfaces[i].element_after].grin;
    if (g.kind == GrinKind::Axial) {
        // n linear in z from n1 to n2: integral dz / n = t ln(n2 / n1) / (n2 - n1).
        const double n2 = system.n_before(i + 1, nm);
        const double b =
            std::abs(n2 - n1) < 1e-12 * n1 ? t / n1 : t * std::log(n2 / n1) / (n2 - n1);
        return {1, b, 0, 1};
    }
    // Radial: n1 is the index on the axis, n0 scaled by the dispersion.
    if (g.A == 0) return {1, t / n1, 0, 1};
    const double k = std::sqrt(std::abs(g.A));
    if (g.A > 0) {
        const double c = std::cos(k * t), s = std::sin(k * t);
        return {c, s / (n1 * k), -n1 * k * s, c};
    }
    // A < 0: the index grows away from the axis and rays diverge exponentially.
    const double c = std::cosh(k * t), s = std::sinh(k * t);
    return {c, s / (n1 * k), n1 * k * s, c};
}

GrinTransit trace_grin_gap(const OpticalSystem& system, size_t i, const Vec3& point,
                           const Vec3& direction, double nm, std::vector<Vec3>* path) {
    const SystemElement& e = system.elements[system.surfaces[i].element_after];
    const GrinMedium medium{e.grin.get(), e.grin_centre, e.index->n(nm) / e.index->n(kLineD)};
    std::vector<Vec3> steps;
    const GrinExit exit =
        trace_grin_ray(medium, *e.solid, system.to_world(point),
                       system.direction_to_world(direction), {}, path ? &steps : nullptr);
    // The first point is `point` itself, already on the path.
    for (size_t k = 1; k < steps.size(); ++k) path->push_back(system.to_system(steps[k]));
    GrinTransit out;
    out.steps = exit.steps;
    if (!exit.left) return out;
    const Vec3 q = system.to_system(exit.hit.point);
    const SystemSurface& next = system.surfaces[i + 1];
    const double r = std::hypot(q.x, q.y);
    // Through the back face, not the rim: the exit point lies on the next surface's sag.
    const double tolerance = 1e-7 * (1.0 + e.semi_diameter);
    if (r > next.semi_diameter + tolerance || std::abs(q.z - next.z_at(r)) > tolerance) return out;
    out.arrived = true;
    out.point = q;
    out.direction = system.frame.to_local(exit.direction);
    return out;
}

}  // namespace lenslab
