#include "scene/interaction.h"

#include <cmath>
#include <limits>

namespace lenslab {

GrinMedium grin_medium_of(const SceneObject& object, const Material& m, double lambda_nm) {
    const GrinProfile& g = *m.grin;
    return {&g, g.has_centre ? g.centre : object.shape->bounds().centre(), m.grin_scale(lambda_nm)};
}

namespace {

// The ray is inside a GRIN solid when its first straight hit is that solid's surface seen
// from inside: the curved path replaces the straight segment.
bool interaction_inside_grin(const Interaction& it, const Ray& ray) {
    return it.material->grin && it.material->transparency > 0.0 && it.object->shape->is_closed() &&
           dot(ray.direction, it.normal()) > 0.0;
}

// Where a GRIN solid is cemented to another (a GRIN crystalline lens between the humours),
// the straight ray may first meet the neighbour's copy of the shared surface, entering it:
// the ray is then inside the GRIN solid on its own side, whose curved path decides where it
// goes. Points the interaction at that solid; false when the ray comes from air or glass.
bool enter_cemented_grin(const Scene& scene, const Ray& ray, Interaction& it) {
    if (!(dot(ray.direction, it.normal()) < 0.0)) return false;  // leaving, not entering
    const int from = scene.solid_beyond(it.hit.object, it.point(), it.normal());
    if (from < 0) return false;
    const Material& m = scene.material_of(from);
    if (!m.grin || !(m.transparency > 0.0)) return false;
    it.hit.object = from;
    it.object = &scene.objects[static_cast<size_t>(from)];
    it.material = &m;
    return true;
}

}  // namespace

bool next_interaction(const Scene& scene, const Ray& ray, double lambda_nm, Interaction& out,
                      std::vector<Vec3>* grin_path) {
    if (grin_path) grin_path->clear();
    if (!scene.intersect(ray, surface_epsilon(ray.origin), std::numeric_limits<double>::infinity(),
                         out.hit)) {
        return false;
    }
    out.object = &scene.objects[out.hit.object];
    out.material = &scene.materials[out.object->material];
    out.direction = ray.direction;
    out.grin_steps = 0;
    if (interaction_inside_grin(out, ray) || enter_cemented_grin(scene, ray, out)) {
        const GrinMedium medium = grin_medium_of(*out.object, *out.material, lambda_nm);
        GrinRayOptions options;
        options.tolerance = scene.render.grin_tolerance;
        const GrinExit exit = trace_grin_ray(medium, *out.object->shape, ray.origin,
                                             normalize(ray.direction), options, grin_path);
        if (!exit.left) {
            // Trapped (or no medium to follow): its light stays inside, absorbed where the
            // straight ray would have met the surface; nothing goes on from there.
            out.beyond = nullptr;
            out.beyond_object = nullptr;
            out.scattering = Scattering{};
            out.grin_steps = exit.steps;
            return true;
        }
        out.hit.surface = exit.hit;
        // Leaving: a grazing exit's direction, off by the tolerance, must not point back in
        // (the surface would take it for light arriving from outside).
        const double outwards = dot(exit.direction, exit.hit.normal);
        out.direction = outwards > 0.0
                            ? exit.direction
                            : normalize(exit.direction + exit.hit.normal * (1e-12 - outwards));
        out.grin_steps = exit.steps;
    }
    const int other = scene.solid_beyond(out.hit.object, out.point(), out.normal());
    out.beyond_object = other < 0 ? nullptr : &scene.objects[static_cast<size_t>(other)];
    out.beyond = other < 0 ? nullptr : &scene.material_of(other);
    out.scattering = scatter_at(out, out.direction, lambda_nm);
    return true;
}

const Absorption* absorption_before(const Interaction& it, const Vec3& d) {
    const Absorption* own = it.material->absorption.get();
    const Absorption* other = it.beyond ? it.beyond->absorption.get() : nullptr;
    if (!own && !other) return nullptr;
    if (!it.object->shape->is_closed() || !(it.material->transparency > 0.0)) return nullptr;
    // Arriving from inside the solid: its glass; from outside: the neighbour's, if cemented.
    return dot(d, it.normal()) > 0.0 ? own : other;
}

double segment_transmittance(const Interaction& it, const Vec3& d, double lambda_nm) {
    const Absorption* a = absorption_before(it, d);
    // t is in units of |d|: a distance for the renderer's unit directions, kept exact for any.
    return a ? a->transmittance(lambda_nm, it.hit.surface.t * std::sqrt(dot(d, d))) : 1.0;
}

namespace {

// The index of `object`'s material at `point`: its GRIN profile's there, else its own.
double index_of_solid(const SceneObject& object, const Material& m, const Vec3& point,
                      double lambda_nm) {
    if (m.grin && object.shape->is_closed())
        return grin_medium_of(object, m, lambda_nm).index(point);
    return m.ior(lambda_nm);
}

}  // namespace

SurfaceIndices indices_at(const Interaction& it, double lambda_nm) {
    const double outside =
        it.beyond ? index_of_solid(*it.beyond_object, *it.beyond, it.point(), lambda_nm)
                  : kOutsideIor;
    return {index_of_solid(*it.object, *it.material, it.point(), lambda_nm), outside};
}

Scattering scatter_at(const Interaction& it, const Vec3& d, double lambda_nm) {
    const Material& m = *it.material;
    if (m.surfaceless) {
        // Index-matched: one transmitted branch, undeviated, at every wavelength.
        Scattering s;
        s.branches[0] = {Event::Refract, d, 1.0};
        s.count = 1;
        return s;
    }
    const bool closed = it.object->shape->is_closed();
    // Either side may be a gradient index (a GRIN lens cemented to glass): each is taken where
    // the ray meets the surface.
    const SurfaceIndices n = indices_at(it, lambda_nm);
    return scatter_with_index(m, n.inside, closed, d, it.normal(), lambda_nm, it.beyond, n.outside);
}

}  // namespace lenslab
