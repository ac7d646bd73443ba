#pragma once
// The parts both builders of the optical system share (system_builder.cpp for coaxial lenses,
// folded_system_builder.cpp for a lens group holding mirrors): where an object sits in the
// scene file, how a lens's two faces become system surfaces.

#include <optional>
#include <string>
#include <utility>

#include "analysis/system/optical_system.h"
#include "geometry/lens/lens_solid.h"

namespace lenslab::system_parts {

// Axes this close to parallel (sine of the angle) and centres this close to the axis
// (relative to the largest lens diameter) count as one axis: hand-typed and generated
// scenes put coaxial lenses on exactly the same line, up to rounding.
constexpr double kAxisAngleTolerance = 1e-9;
constexpr double kAxisOffsetTolerance = 1e-9;
// Facing surfaces closer than this (relative to the system's size) are one cemented
// interface; the lead's shorthand and hand-written doublets place them exactly.
constexpr double kCementTolerance = 1e-9;

// The scene file's entry the object came from, "objects[3]" or "objects[3].elements[1]".
std::string object_path(const Scene& scene, int i);
// The path with the object's name: "objects[3] ('crown')".
std::string describe_object(const Scene& scene, int i);
std::string format(double v);

struct Placed {
    int object;
    const LensPrescription* lens;
    double orientation;      // +1: lens axis along the system axis
    double z_first, z_last;  // the faces light meets first and last
    double travel = 1.0;     // the direction light crosses it (-1: after a mirror)
    // A lens group element decentred or tilted from the axis: its surfaces get poses, z_first
    // and z_last stay those of the element as designed.
    bool posed = false;
};

// The world vertices of a lens's faces: the one light meets first, then the other.
std::pair<Vec3, Vec3> vertices_met(const LensPrescription& p, double orientation);
SurfaceSpan measure_aim_span(const LensSurface& shape, double semi_diameter);
// The two surfaces of a lens in the order light meets them, as system surfaces (one shared
// with the lens before when cemented to it).
void add_surfaces(const Placed& p, int element, OpticalSystem& system);
SystemElement make_element(const Scene& scene, int object);
// Refuses a lens that lets no light through.
void check_lens_transparent(const Scene& scene, int i);
// Whether a face is not a surface of revolution (a sag in x and y, a biconic, ...).
bool has_freeform_face(const LensPrescription& p);

// A folded system: the group's elements in its order (folded_system_builder.cpp).
std::optional<int> folded_group(const Scene& scene, std::optional<int> lens);
OpticalSystem build_folded_system(const Scene& scene, int group);

}  // namespace lenslab::system_parts
