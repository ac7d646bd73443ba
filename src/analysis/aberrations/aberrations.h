#pragma once
// What a real lens does to a collimated beam on its axis, by exact ray tracing: the
// longitudinal spherical aberration against ray height, the spot diagram at the paraxial
// focus and at the best focus (the image plane of least RMS spot radius), and the
// longitudinal chromatic aberration between the F and C lines.

#include <vector>

#include "analysis/system/optical_system.h"
#include "analysis/system/paraxial.h"

namespace lenslab {

struct LsaPoint {
    double height;      // entrance height of the (meridional) ray
    double lsa;         // where it crosses the axis minus the paraxial focus (< 0: in front)
    double transverse;  // its height in the paraxial focal plane
};

struct SpotDiagram {
    double z = 0;                 // the image plane (system z)
    double rms_radius = 0;        // RMS distance of the ray hits from their centroid
    double geometric_radius = 0;  // largest distance from the centroid
    double centroid_x = 0, centroid_y = 0;
    std::vector<Vec3> points;  // the hits (z = the plane)
};

// Rays that left the last surface, each a point on it and a unit direction.
struct ExitRay {
    Vec3 point, direction;
};

// Largest entrance height (up to the first surface's semi-diameter) at which a ray parallel
// to the axis still passes every surface at this wavelength.
double usable_aperture_radius(const OpticalSystem& system, double wavelength_nm);

// The hexapolar sampling of a unit pupil: the centre and `rings` rings of 6, 12, ... points at
// radii 1/rings, 2/rings, ..., 1 (odd rings turned by half a step), each point standing for
// about an equal share of the pupil's area: Zemax's "hexapolar" ray density of `rings`.
struct PupilPoint {
    double x, y;
};
std::vector<PupilPoint> hexapolar_pupil(int rings);

// A collimated beam along the axis with radius `aperture_radius`, sampled on the hexapolar
// grid of `rings`. Returns the rays that passed; `lost` counts the others.
std::vector<ExitRay> trace_collimated_beam(const OpticalSystem& system, double wavelength_nm,
                                           double aperture_radius, int rings, int* lost);

// LSA and transverse aberration of meridional rays at `samples` heights up to the aperture.
std::vector<LsaPoint> longitudinal_spherical_aberration(const OpticalSystem& system,
                                                        const ParaxialResult& paraxial,
                                                        double aperture_radius, int samples);

SpotDiagram spot_at(const std::vector<ExitRay>& rays, double z_plane);

// The plane where the RMS spot radius is least. Each ray's hit moves linearly with the
// plane's position, so the centroid-referred mean square radius is a quadratic in z and its
// minimum is found in closed form. `z_reference` is any plane near focus.
double best_focus_z(const std::vector<ExitRay>& rays, double z_reference);

// z where the entrance rays start: in front of every surface.
double beam_start_z(const OpticalSystem& system);

}  // namespace lenslab
