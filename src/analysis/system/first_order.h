#pragma once
// First-order (paraxial) data of a system with an aperture stop: the entrance and exit
// pupils, F-number, working F-number, numerical aperture, Lagrange invariant and
// magnification, and the marginal and chief rays that give them (Welford, Aberrations of
// Optical Systems, ch. 2-3; Smith, Modern Optical Engineering, 4th ed., ch. 6).
//
// The aperture stop is one surface of the system; its rim limits the axial beam. The
// entrance pupil is the stop's paraxial image through the surfaces before it (in object
// space), the exit pupil its image through the surfaces after it (in image space).
// Marginal ray: from the axial object point through the rim of the stop. Chief ray: from the
// edge of the field (the largest field asked for) through the centre of the stop.
//
// Positions are axial distances: the entrance pupil's from the first vertex, the exit
// pupil's and the image's from the last vertex, > 0 when the point lies behind (to +z of)
// that vertex, as in Zemax and rayoptics. Lagrange invariant H = n (ū y - u ȳ) (u, y: the
// marginal ray; ū, ȳ: the chief ray), evaluated in object space; with a positive field
// angle the chief ray climbs (ū > 0), so H > 0 for a positive lens at infinity.

#include <optional>
#include <string>
#include <vector>

#include "analysis/system/paraxial.h"
#include "analysis/system/paraxial_ray.h"

namespace lenslab {

// How real rays from a field point are aimed at a point (px, py) of the pupil
// (analysis/system/ray_aiming.h): through the real aperture stop, found by iteration, or straight
// at the paraxial entrance pupil (Zemax's default, "ray aiming off"), the stop then met wherever
// the pupil's aberrations take the ray.
enum class RayAiming { Real, Paraxial };
const char* ray_aiming_name(RayAiming aiming);  // "real", "paraxial"
// The aiming a name names; none for another name.
std::optional<RayAiming> ray_aiming_named(const std::string& name);

struct FirstOrderOptions {
    double wavelength_nm = kLineD;
    int stop = 0;         // the aperture stop: a surface index (0-based)
    double epd = 0;       // entrance pupil diameter; 0: set by f_number, else the stop's rim
    double f_number = 0;  // sets the entrance pupil diameter to EFL / f_number
    // Distance from the object to the first vertex (> 0: the object in front); none: the
    // object at infinity.
    std::optional<double> object_distance;
    // Field points: angles in degrees for an object at infinity, object heights otherwise.
    std::vector<double> fields{0.0};
    RayAiming ray_aiming = RayAiming::Real;
};

struct Pupil {
    double position = 0;  // see above; +-infinity for a pupil at infinity (telecentric)
    double diameter = 0;
};

struct FirstOrder {
    double wavelength_nm = 0;
    int stop = 0;
    double stop_semi_diameter = 0;  // the marginal ray's height at the stop
    double efl = 0, bfl = 0;
    double f_number = 0;          // EFL / entrance pupil diameter
    double working_f_number = 0;  // 1 / (2 n' |u'|), u' the marginal ray's image-space slope
    double na = 0;                // image-space numerical aperture n' |u'| (paraxial)
    Pupil entrance_pupil, exit_pupil;
    double lagrange_invariant = 0;
    std::optional<double> magnification;     // finite object only: n u / (n' u')
    double image_position = 0;               // paraxial image, from the last vertex
    double image_height = 0;                 // the chief ray's height there
    std::optional<double> object_distance;   // as in FirstOrderOptions
    double field = 0;                        // the field point the chief ray comes from
    RayAiming ray_aiming = RayAiming::Real;  // as in FirstOrderOptions
    ParaxialRay marginal, chief;
    // A decentred or tilted system (OpticalSystem::coaxial() false): the parabasal figures
    // about the chief ray of the central field (parabasal.h), which set efl, bfl, the image
    // position and height, the F-numbers, NA and magnification; the pupils, the marginal and
    // chief paraxial rays and the Lagrange invariant stay those of the system as designed.
    std::optional<ParaxialResult> parabasal;
};

// Throws SceneError when the entrance pupil lies at infinity, or the object sits at the
// entrance pupil, or the stop index is out of range.
FirstOrder first_order(const OpticalSystem& system, const ParaxialResult& paraxial,
                       const FirstOrderOptions& options);

}  // namespace lenslab
