#pragma once
// The gap between two surfaces of a lens system when the lens there has a gradient index
// (SystemElement::grin): how paraxial and real rays cross it. In homogeneous glass the
// paraxial transfer is (y, nu) -> (y + t u, nu); in a radial profile n = n0 (1 - A r^2 / 2)
// the paraxial ray equation y'' = -A y makes it a rotation,
//   y' = y cos(g t) + nu sin(g t) / (n0 g),   nu' = -n0 g y sin(g t) + nu cos(g t),  g = sqrt(A)
// (Gomez-Reino, Perez and Bao, "Gradient-Index Optics", 2002, ch. 2; the pitch is 2 pi / g);
// in an axial profile, n linear in z, n u is constant and y' = y + nu * integral dz / n.
// Real rays follow the ray equation through the lens solid (scene/grin_ray.h).

#include <vector>

#include "analysis/system/optical_system.h"

namespace lenslab {

// (y, n u) at the vertex plane of surface i, after its refraction, to (y, n u) at the vertex
// plane of surface i + 1, before its refraction: y' = a y + b nu, nu' = c y + d nu.
struct GapTransfer {
    double a = 1, b = 0, c = 0, d = 1;
};

GapTransfer gap_transfer(const OpticalSystem& system, size_t i, double wavelength_nm);

// A real ray inside the lens behind surface i, from `point` on that surface along unit
// `direction` (system coordinates), to surface i + 1. Only for a lens of gradient index.
struct GrinTransit {
    bool arrived = false;  // false: it left through the rim, or was trapped
    Vec3 point, direction;
    int steps = 0;  // integration steps
};

// `path`, when given, is extended by the integrator's points after `point` (system
// coordinates), to the exit point.
GrinTransit trace_grin_gap(const OpticalSystem& system, size_t i, const Vec3& point,
                           const Vec3& direction, double wavelength_nm,
                           std::vector<Vec3>* path = nullptr);

// Whether the medium behind surface i (before surface i + 1) has a gradient index.
bool grin_gap(const OpticalSystem& system, size_t i);

}  // namespace lenslab
