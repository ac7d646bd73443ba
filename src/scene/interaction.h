#pragma once
// The step every tracer repeats: find the next surface along a ray and how its material
// splits the light arriving there. Shared by the Whitted integrator, photon tracing and
// `lenslab trace`, so all three see the same optics.

#include "scene/scattering.h"
#include "scene/scene.h"

namespace lenslab {

struct Interaction {
    SceneHit hit;
    const SceneObject* object = nullptr;
    const Material* material = nullptr;
    const Material* beyond = nullptr;  // the cemented glass on the other side, or nullptr: air
    Scattering scattering;

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

// How the interaction's surface splits light arriving along `d` at `lambda_nm`.
Scattering scatter_at(const Interaction& it, const Vec3& d, double lambda_nm);

// False when the ray leaves the scene. The ray's origin is taken to lie on the surface it
// left, so hits closer than surface_epsilon(origin) are ignored. Refraction is computed for
// the wavelength `lambda_nm`.
bool next_interaction(const Scene& scene, const Ray& ray, double lambda_nm, Interaction& out);

}  // namespace lenslab
