#pragma once
// Field curvature and distortion against field, from real rays, as lens-design programs plot
// them: for each field from 0 to the largest, at each wavelength,
// - the tangential and sagittal foci: where the two rays through the stop points (0, ±δ)
//   cross each other in the meridional plane, and the two through (±δ, 0) cross in the
//   sagittal direction (both beside the chief ray, δ = 0.01 of the stop radius: the
//   differential rays of Coddington's equations), as z distances from the image plane,
//   > 0 behind it;
// - distortion: the real chief ray's height in the image plane against the paraxial chief
//   ray's (of the primary wavelength, scaled linearly with tan θ or the object height),
//   (y_real - y_paraxial) / y_paraxial.

#include <cmath>
#include <optional>
#include <vector>

#include "analysis/system/first_order.h"

namespace lenslab {

// δ: the differential rays' stop coordinate, of the stop radius.
inline constexpr double kFieldCurveDifferentialPupil = 0.01;

struct FieldCurvePoint {
    double field = 0;
    double tangential = NAN, sagittal = NAN;  // focus minus image plane, along z
    double chief_height = NAN;                // real, in the image plane
    double paraxial_height = NAN;             // primary wavelength, in the image plane
    double distortion = NAN;                  // fraction; NaN on the axis
};

struct FieldCurve {
    double wavelength_nm = 0;
    std::vector<FieldCurvePoint> points;
};

struct FieldCurves {
    double image_z = 0;              // system z
    std::vector<FieldCurve> curves;  // one per wavelength
};

struct FieldCurveOptions {
    double max_field = 0;  // degrees or object height; the curves run from 0 to it
    int points = 11;       // fields sampled, evenly from 0 to max_field (one when it is 0)
    std::vector<double> wavelengths;  // empty: the first-order block's
    std::optional<double> image_z;    // none: the paraxial image plane
};

// The paraxial chief ray's height at z for `field`, from the first-order block's chief ray
// (linear in tan θ at infinity, in the object height for a finite object); NaN when that
// block's field is 0.
double paraxial_chief_height(const OpticalSystem& system, const FirstOrder& first_order,
                             double field, double z);

FieldCurves field_curves(const OpticalSystem& system, const FirstOrder& first_order,
                         const FieldCurveOptions& options);

}  // namespace lenslab
