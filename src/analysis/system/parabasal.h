#pragma once
// First-order figures of a system that is not rotationally symmetric (decentred or tilted
// surfaces), as Zemax and CODE V give them: about a real reference ray, the chief ray of the
// central field, rather than about the axis. Rays a small step from it in height and in
// angle, traced exactly, give the transfer matrix of its neighbourhood in each section
// (parabasal optics; for a coaxial system they reproduce the paraxial matrix).

#include <optional>

#include "analysis/system/optical_system.h"
#include "analysis/system/paraxial.h"
#include "math/ray.h"

namespace lenslab {

// The reference ray's neighbourhood: the (y, n u) transfer matrix of each section, from the
// plane across the reference ray at its start to the plane across it where it leaves the last
// surface. y and x are measured along the system's y and x as far as the ray's turns allow.
struct ParabasalMatrices {
    Ray reference;  // in object space
    Vec3 exit_point, exit_direction;
    double n_object = 1, n_image = 1;  // unsigned
    struct Section {
        double a = 1, b = 0, c = 0, d = 1;
    } y, x;
};

// None when the reference ray or a ray beside it does not pass the system.
std::optional<ParabasalMatrices> parabasal_matrices(const OpticalSystem& system,
                                                    const Ray& reference, double wavelength_nm);

// The paraxial figures (paraxial.h) read off the y-z section's matrix: focal lengths along
// the reference ray, focal points and principal planes at the system z of the points on it.
// Throws SceneError as paraxial_trace does for an afocal system.
ParaxialResult parabasal_paraxial(const OpticalSystem& system, const ParabasalMatrices& m,
                                  double wavelength_nm);

}  // namespace lenslab
