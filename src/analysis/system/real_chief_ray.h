#pragma once
// The real (exactly traced) chief ray: from the field point of the first-order data, aimed
// so that it crosses the aperture stop at its centre, and where it meets the paraxial image
// plane. Its height against the paraxial image height is the real-ray distortion
// (y_real - y_paraxial) / y_paraxial at that field.

#include <optional>

#include "analysis/system/first_order.h"

namespace lenslab {

struct RealChiefRay {
    double image_height = 0;  // in the paraxial image plane
    double distortion = 0;    // relative: (real - paraxial) / paraxial; 0 on the axis
};

// Aimed at the centre of the stop (ray_aiming.h). None when the ray cannot be
// traced (it misses a surface or is totally reflected) or the aim does not converge.
std::optional<RealChiefRay> trace_real_chief_ray(const OpticalSystem& system,
                                                 const FirstOrder& first_order);

}  // namespace lenslab
