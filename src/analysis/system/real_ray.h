#pragma once
// Exact (real-ray) sequential trace through a coaxial system: the ray meets each surface in
// turn, at its true shape (LensSurface::intersect), and refracts there by Snell's law or
// reflects at a mirror.

#include <vector>

#include "analysis/system/optical_system.h"
#include "math/ray.h"

namespace lenslab {

enum class RayFate {
    Passed,     // left the last surface
    Missed,     // passed outside a surface's semi-diameter (clipped by the lens edge) or
                // through a mirror's central hole
    Reflected,  // total internal reflection at a surface
};

struct RealRay {
    RayFate fate = RayFate::Passed;
    int surface = -1;          // where a ray that did not pass was stopped
    std::vector<Vec3> points;  // start, then the point on each surface met (system coords)
    Vec3 direction;            // unit direction after the last surface it crossed
    const Vec3& exit_point() const { return points.back(); }
};

enum class Rims {
    Clip,    // a ray outside a surface's semi-diameter is Missed there
    Ignore,  // surfaces extend past their rims (SystemSurface::aim_span): for ray aiming
};

// Traces `ray` (system coordinates, unit direction with d.z > 0) at a wavelength (in air).
// Behind a mirror the ray travels towards -z; RealRay::direction then has d.z < 0.
// `path`, when given, receives the ray as a polyline to draw: the points of `points`, with
// the integrator's points between two surfaces where a gradient index curves the ray.
RealRay trace_real_ray(const OpticalSystem& system, const Ray& ray, double wavelength_nm,
                       Rims rims = Rims::Clip, std::vector<Vec3>* path = nullptr);

// What trace_real_ray refracts with at each surface at a wavelength (in air), worked out once
// for the many rays of a beam: n_before / n_after, or NaN next to a gradient index, where the
// ratio depends on where the ray meets the surface.
struct IndexRatios {
    double wavelength_nm = 0;
    std::vector<double> ratios;
};
IndexRatios index_ratios(const OpticalSystem& system, double wavelength_nm);

// As above with index_ratios(system, wavelength_nm) given: the same ray, bit for bit.
RealRay trace_real_ray(const OpticalSystem& system, const Ray& ray, const IndexRatios& indices,
                       Rims rims = Rims::Clip, std::vector<Vec3>* path = nullptr);

// As above into `out`, whose points keep their storage from ray to ray: a beam's rays cost
// no allocation each.
void trace_real_ray_into(RealRay& out, const OpticalSystem& system, const Ray& ray,
                         const IndexRatios& indices, Rims rims = Rims::Clip,
                         std::vector<Vec3>* path = nullptr);

// Where a ray leaving along `direction` from `point` crosses the plane z = z_plane (x, y).
Vec3 at_plane(const Vec3& point, const Vec3& direction, double z_plane);

}  // namespace lenslab
