#pragma once
// First-order (paraxial) optics of a coaxial system: the y-nu trace written as ray-transfer
// (ABCD) matrices acting on (height y, reduced angle n u). From the system matrix come the
// power, the effective focal length, the focal points and the principal planes (Smith,
// Modern Optical Engineering, 4th ed., sections 2.5-2.6 and 3.3; Hecht, Optics, 5th ed.,
// section 6.2).

#include "analysis/system/optical_system.h"
#include "math/ray.h"

namespace lenslab {

struct ParaxialResult {
    double wavelength_nm = 0;
    double power = 0;  // Φ = -C, in inverse length units
    // Effective (equivalent) focal length 1/Φ; positive for a converging system.
    double efl = 0;
    // Back focal length: from the last vertex to the rear focal point F' (positive when F'
    // lies behind the last vertex). Front focal length: from the front focal point F to the
    // first vertex (positive when F lies in front of it). Both follow Hecht's thick-lens
    // b.f.l. and f.f.l., so for a thin lens efl = bfl = ffl.
    double bfl = 0;
    double ffl = 0;
    // Axial positions in system z (0 at the first vertex).
    double z_rear_focus = 0, z_front_focus = 0;
    double z_rear_principal = 0, z_front_principal = 0;
    // The system matrix from the first vertex to the last, on (y, n u).
    double a = 1, b = 0, c = 0, d = 1;
    // Parabasal figures of a decentred or tilted system (parabasal.h): about the chief ray of
    // the central field, the matrix the y-z section's from its start to where it leaves the
    // last surface; efl_x the x-z section's focal length and rear_focus the focal point.
    bool parabasal = false;
    double efl_x = 0;
    Vec3 rear_focus;
    Ray reference;  // the chief ray it is about, in object space
};

// Throws SceneError when the system has no focus (zero power: afocal).
ParaxialResult paraxial_trace(const OpticalSystem& system, double wavelength_nm);

}  // namespace lenslab
