#pragma once
// How a material splits light arriving along a direction: into the specular branches
// (mirror reflection, Fresnel reflection and refraction at the dielectric interface, total
// internal reflection) and the diffuse part. One place for the whitted integrator, the ray
// tracer of `lenslab trace` and, later, photon tracing.

#include <algorithm>
#include <array>

#include "math/frame.h"
#include "math/rng.h"
#include "math/sampling.h"
#include "math/vec3.h"
#include "scene/material.h"

namespace lenslab {

enum class Event { Refract, Reflect, Tir, Absorb, Escape };

const char* event_name(Event e);

struct Branch {
    Event event = Event::Reflect;
    Vec3 direction;     // unit, leaving the surface
    double weight = 0;  // fraction of the arriving power carried by this branch
};

struct Scattering {
    std::array<Branch, 2> branches;  // at most one reflected and one transmitted branch
    int count = 0;
    double diffuse = 0;  // fraction scattered diffusely (the `absorb` part of a trace)
    // The refraction bent each wavelength differently: only `lambda_nm` follows the
    // refracted branch (the other sampled wavelengths must be dropped from it).
    bool dispersive = false;
};

// One event at a hit, chosen with probabilities (Russian roulette): the diffuse part with
// probability `diffuse_probability`, else each specular branch with its weight, else
// absorption (neither set). Every integrator and photon tracer picks its events here.
struct EventPick {
    bool diffuse = false;
    const Branch* branch = nullptr;  // the specular branch taken, if one was
};

// `u` is a uniform number in [0, 1) scaled by the caller (by the sum of the probabilities
// when absorption is excluded).
inline EventPick pick_event(const Scattering& s, double diffuse_probability, double u) {
    if (u < diffuse_probability) return {true, nullptr};
    u -= diffuse_probability;
    for (int i = 0; i < s.count; ++i) {
        if (u < s.branches[i].weight) return {false, &s.branches[i]};
        u -= s.branches[i].weight;
    }
    return {};
}

// Probability that a path or photon goes on with a diffuse bounce, for pick_event: the
// diffuse share times the albedo's largest component, so dark surfaces end more paths (0 on
// a black one). The survivor carries albedo × diffuse share / this.
inline double diffuse_continuation(const Scattering& s, const Material& m) {
    if (!(s.diffuse > 0.0) || m.color.is_black()) return 0.0;
    return s.diffuse * std::min(1.0, m.color.max_component());
}

// The diffuse bounce's direction: cosine-distributed about `facing` (the side arrived from).
inline Vec3 sample_diffuse_direction(const Vec3& facing, Rng& rng) {
    return Frame::from_axis(facing).to_world(
        sample_cosine_hemisphere(rng.uniform(), rng.uniform()));
}

// Medium around the objects: air, n = 1 (indices are relative to it, as catalogues give them).
inline constexpr double kOutsideIor = 1.0;

// `d`: unit arriving direction; `outward_normal`: unit, out of the solid (for an open
// surface, its face normal); `closed`: whether the surface bounds a volume. An open
// transparent surface is a thin pane: light passes straight through, and its two faces
// reflect (R'_s + R'_p) / 2 of it, R' = 2R / (1 + R) per polarisation (incoherent multiple
// reflections, Hecht section 9.7; absorption neglected).
// The index is taken at `lambda_nm` (in air; see optics/air_index.h). `beyond` is the transparent
// solid on the other side of a closed surface (a cemented element, Scene::medium_beyond), or
// nullptr for air: the interface then refracts by the ratio of the two glasses' indices.
Scattering scatter(const Material& m, bool closed, const Vec3& d, const Vec3& outward_normal,
                   double lambda_nm, const Material* beyond = nullptr);
// The same with the indices given: the inside's `n_inside` and the other side's `n_beyond`
// (a GRIN solid's, at the hit point; air's when `beyond` is null).
Scattering scatter_with_index(const Material& m, double n_inside, bool closed, const Vec3& d,
                              const Vec3& outward_normal, double lambda_nm, const Material* beyond,
                              double n_beyond);

}  // namespace lenslab
