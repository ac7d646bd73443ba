#pragma once
// The step every tracer repeats: find the next surface along a ray and how its material
// splits the light arriving there. Shared by the Whitted integrator, photon tracing and
// `lenslab trace`, so all three see the same optics.

#include <vector>

#include "scene/grin_ray.h"
#include "scene/scattering.h"
#include "scene/scene.h"

namespace lenslab {

struct Interaction {
    SceneHit hit;
    const SceneObject* object = nullptr;
    const Material* material = nullptr;
    const Material* beyond = nullptr;  // the cemented glass on the other side, or nullptr: air
    const SceneObject* beyond_object = nullptr;  // the solid it fills
    Scattering scattering;
    // Unit direction in which the ray arrives: the ray's own, or, leaving a GRIN solid, the
    // direction its curved path has at the surface.
    Vec3 direction;
    int grin_steps = 0;  // integration steps through a GRIN solid to get here (0: straight)

    const Vec3& point() const { return hit.surface.point; }
    const Vec3& normal() const { return hit.surface.normal; }  // outward
};

// The absorbing medium the ray crossed to reach the interaction along `d`: the solid it is
// leaving, or the cemented neighbour it comes from; nullptr when that medium does not absorb
// (air, a glass without k data), so clear glass costs two pointer tests per hit.
const Absorption* absorption_before(const Interaction& it, const Vec3& d);

// The Beer-Lambert fraction of light left after the segment that reached `it` along `d`, at
// `lambda_nm`: 1 through a medium that does not absorb.
double segment_transmittance(const Interaction& it, const Vec3& d, double lambda_nm);

// The refractive indices on either side of the interaction's surface at `lambda_nm`: its
// solid's (a GRIN solid's at the hit point) and what lies outside (the cemented neighbour's,
// else air's kOutsideIor).
struct SurfaceIndices {
    double inside = 1, outside = 1;
};
SurfaceIndices indices_at(const Interaction& it, double lambda_nm);

// How the interaction's surface splits light arriving along `d` at `lambda_nm`. A GRIN
// solid's index is taken at the hit point.
Scattering scatter_at(const Interaction& it, const Vec3& d, double lambda_nm);

// False when the ray leaves the scene. The ray's origin is taken to lie on the surface it
// left, so hits closer than surface_epsilon(origin) are ignored. Refraction is computed for
// the wavelength `lambda_nm`. A ray inside a GRIN solid (one whose first straight hit is the
// solid's surface from inside) follows the curved path through it (scene/grin_ray.h) to the
// surface; `grin_path`, when given, receives that path's points (else it is left empty).
// Nothing may lie inside a GRIN solid.
bool next_interaction(const Scene& scene, const Ray& ray, double lambda_nm, Interaction& out,
                      std::vector<Vec3>* grin_path = nullptr);

// The GRIN medium of `object` (whose material has a profile) at `lambda_nm`.
GrinMedium grin_medium_of(const SceneObject& object, const Material& m, double lambda_nm);

}  // namespace lenslab
