#pragma once
// OPD fans per field and wavelength, as lens-design programs plot them ("OPD Fan"): the
// wavefront's optical path difference (field_wavefront.h: against each wavelength's chief ray
// and its reference sphere, in waves) along the two lines of the stop through its centre.
// Tangential fan: stop points (0, py), py from -1 to 1; sagittal: (px, 0). The same layout as
// the transverse ray fans (ray_fans.h), values in waves instead of lengths.

#include "analysis/aberrations/ray_fans.h"

namespace lenslab {

// options.image_z: the plane of the reference spheres' centres (none: the paraxial image).
// Values are NaN where a ray was vignetted or could not be aimed, and the whole fan where the
// chief ray of that wavelength does not pass. FieldFans::reference: the primary wavelength's
// chief ray in the image plane.
RayFans opd_fans(const OpticalSystem& system, const FirstOrder& first_order,
                 const RayFanOptions& options);

}  // namespace lenslab
