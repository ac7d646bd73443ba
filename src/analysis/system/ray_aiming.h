#pragma once
// Real rays from one field point aimed through chosen points of the aperture stop ("ray
// aiming" in Zemax and rayoptics): an off-axis beam then fills the stop exactly, however the
// real entrance pupil is shifted or distorted against the paraxial one.
//
// A point of the stop is given in normalised pupil coordinates (px, py): the unit circle is
// the stop's rim at the first-order data's stop semi-diameter, py along the meridional (y)
// direction, in which the field lies. Each ray starts from the field point: for an object at
// infinity a collimated ray at the field angle (degrees, in the y-z plane) crossing the
// plane z = beam_start_z at (a, b); for a finite object a ray from (0, h, -object_distance)
// with slopes (a, b). (a, b) is found by Newton's method from the paraxial aim through the
// entrance pupil, with a finite-difference Jacobian; rays at every wavelength are aimed at
// the same stop points.

#include <optional>

#include "analysis/system/first_order.h"
#include "analysis/system/real_ray.h"

namespace lenslab {

class RayAimer {
public:
    // `field`: an angle in degrees (object at infinity) or an object height (finite object,
    // as in first_order.object_distance), in y; `field_x` the same in x (a field point off the
    // meridional plane: the direction (tan x, tan y, 1) for angles).
    RayAimer(const OpticalSystem& system, const FirstOrder& first_order, double field,
             double wavelength_nm, double field_x = 0.0);

    // The ray from the field point that crosses the stop at (px, py), with the surfaces
    // taken past their rims (Rims::Ignore). None when no such ray exists (it is totally
    // reflected before the stop, or the surface shapes end) or the aim does not converge.
    // With first_order.ray_aiming Paraxial, the ray through (px, py) of the paraxial
    // entrance pupil instead, without iteration.
    std::optional<Ray> aim(double px, double py) const;

    // That ray traced through every surface with their rims: its fate says whether a lens
    // rim before or after the stop vignettes it.
    std::optional<RealRay> trace(double px, double py) const;

private:
    // The start of the ray for aim (a, b).
    Ray candidate(double a, double b) const;
    // Where the ray of aim (a, b) crosses the stop surface (in its own frame when decentred or
    // tilted); none when it does not get there.
    std::optional<Vec3> at_stop(double a, double b) const;

    const OpticalSystem& system_;
    const FirstOrder& first_order_;
    double field_, field_x_;
    IndexRatios ratios_;  // index_ratios at the wavelength, once for every ray
    double scale_;        // the system's size, for tolerances and difference steps
    double z_start_ = 0;  // object at infinity: where the collimated rays start
    // Object at infinity: the field direction.
    double direction_x_ = 0, direction_y_ = 0, direction_z_ = 1;
};

}  // namespace lenslab
