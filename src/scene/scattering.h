#pragma once
// How a material splits light arriving along a direction: into the specular branches
// (mirror reflection, Fresnel reflection and refraction at the dielectric interface, total
// internal reflection) and the diffuse part. One place for the whitted integrator, the ray
// tracer of `lenslab trace` and, later, photon tracing.

#include <array>

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

// The specular branch whose share of the arriving power holds `u` (a uniform number, the
// diffuse share already taken off), or nullptr for the rest: Russian roulette on the
// branches, each chosen with probability equal to its weight.
inline const Branch* roulette_branch(const Scattering& s, double u) {
    for (int i = 0; i < s.count; ++i) {
        if (u < s.branches[i].weight) return &s.branches[i];
        u -= s.branches[i].weight;
    }
    return nullptr;
}

// Medium around the objects: air, taken as vacuum-like n = 1.
inline constexpr double kOutsideIor = 1.0;

// `d`: unit arriving direction; `outward_normal`: unit, out of the solid (for an open
// surface, its face normal); `closed`: whether the surface bounds a volume. An open
// transparent surface is a thin pane: light passes straight through, and its two faces
// reflect (R'_s + R'_p) / 2 of it, R' = 2R / (1 + R) per polarisation (incoherent multiple
// reflections, Hecht section 9.7; absorption neglected).
// The index is taken at `lambda_nm` (vacuum wavelength). `beyond` is the transparent solid
// on the other side of a closed surface (a cemented element, Scene::medium_beyond), or
// nullptr for air: the interface then refracts by the ratio of the two glasses' indices.
Scattering scatter(const Material& m, bool closed, const Vec3& d, const Vec3& outward_normal,
                   double lambda_nm, const Material* beyond = nullptr);

}  // namespace lenslab
