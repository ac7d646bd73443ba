#pragma once
// The RMS spot radius of one field point over several wavelengths together, as lens-design
// programs report it and optimise it: each wavelength's beam aimed through the same
// hexapolar grid of the stop (field_beam.h), every ray that passes weighted by its
// wavelength's weight, the radius taken about the weighted centroid of all of them in the
// image plane (so lateral colour counts, as it blurs the image).

#include <vector>

#include "analysis/system/field_beam.h"

namespace lenslab {

struct PolychromaticSpot {
    double rms_radius = 0;
    double centroid_x = 0, centroid_y = 0;
    int rays = 0;  // traced, all wavelengths
    int lost = 0;  // of those, vignetted or not aimable
};

// `weights` has one entry per wavelength (empty: all equal); `image_z` is the image plane in
// system z. With no ray through, rms_radius is NaN.
// The same from beams already traced, one per wavelength, `weights` in their order (empty:
// all equal).
// `deviations`, when given, receives each passing ray's offset from the centroid, x then y,
// scaled by √(w / Σw): their squares sum to the mean square radius. The optimiser hands them
// to damped least squares as separate residuals (as lens-design programs build an RMS spot
// from ray operands), so its Gauss-Newton model sees the spot's shape, not only its size.
PolychromaticSpot polychromatic_spot(const std::vector<FieldBeam>& beams,
                                     const std::vector<double>& weights, double image_z,
                                     std::vector<double>* deviations = nullptr);

PolychromaticSpot polychromatic_rms_spot(const OpticalSystem& system, const FirstOrder& first_order,
                                         double field, const std::vector<double>& wavelengths,
                                         const std::vector<double>& weights, int rings,
                                         double image_z, std::vector<double>* deviations = nullptr);

}  // namespace lenslab
