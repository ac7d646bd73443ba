#include "analysis/aberrations/focal_shift.h"

#include <algorithm>

namespace lenslab {

namespace {

double image_position_at(const OpticalSystem& system, FirstOrderOptions options, double nm) {
    options.wavelength_nm = nm;
    return first_order(system, paraxial_trace(system, nm), options).image_position;
}

}  // namespace

FocalShift chromatic_focal_shift(const OpticalSystem& system, const FirstOrderOptions& options,
                                 double from_nm, double to_nm, int points) {
    check_wavelength(system, from_nm, "--band");
    check_wavelength(system, to_nm, "--band");
    FocalShift r;
    r.reference_nm = options.wavelength_nm;
    const double reference = image_position_at(system, options, r.reference_nm);
    const int n = std::max(points, 2);
    for (int i = 0; i < n; ++i) {
        const double nm = from_nm + (to_nm - from_nm) * i / (n - 1);
        r.wavelengths.push_back(nm);
        r.shift.push_back(image_position_at(system, options, nm) - reference);
    }
    return r;
}

}  // namespace lenslab
