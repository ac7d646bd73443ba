#pragma once
// The chromatic focal shift over a band, as lens-design programs plot it: the paraxial image
// position at each wavelength minus that at the reference (primary) wavelength, for the
// object of the first-order options (at infinity: BFL(λ) - BFL(λ0)); > 0: that colour
// focuses behind the reference.

#include <vector>

#include "analysis/system/first_order.h"

namespace lenslab {

struct FocalShift {
    double reference_nm = 0;
    std::vector<double> wavelengths;  // evenly across the band, both ends included
    std::vector<double> shift;        // image position minus the reference's
};

// `options` as for first_order() (its wavelength is the reference); `points` ≥ 2 wavelengths
// from `from_nm` to `to_nm`. Throws SceneError when a wavelength lies outside a glass's range.
FocalShift chromatic_focal_shift(const OpticalSystem& system, const FirstOrderOptions& options,
                                 double from_nm, double to_nm, int points);

}  // namespace lenslab
