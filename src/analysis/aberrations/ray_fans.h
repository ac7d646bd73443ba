#pragma once
// Transverse ray aberration fans per field and wavelength, as lens-design programs plot
// them: rays aimed (ray_aiming.h) through a line of points across the stop, and where each
// lands in the image plane relative to the chief ray of the primary wavelength at that
// field (Zemax's reference, so the fans of the other wavelengths show lateral and axial
// colour). Tangential fan: stop points (0, py), py from -1 to 1, error ε_y; sagittal fan:
// (px, 0), px from -1 to 1, error ε_x. y is the meridional direction, in which the field
// lies.

#include <optional>
#include <vector>

#include "analysis/system/first_order.h"
#include "analysis/system/real_ray.h"

namespace lenslab {

struct RayFanOptions {
    // Angles in degrees (object at infinity) or object heights (finite object).
    std::vector<double> fields{0.0};
    std::vector<double> wavelengths;  // nm; empty: the first-order block's
    int points = 21;                  // along each fan, evenly from -1 to 1 (at least 2)
    // The image plane in system z; none: the paraxial image plane of the first-order block.
    std::optional<double> image_z;
};

struct RayFan {
    double wavelength_nm = 0;
    // ε at each pupil coordinate of RayFans::pupil; NaN where the ray was vignetted or
    // could not be aimed, or the reference chief ray failed.
    std::vector<double> tangential, sagittal;
};

struct FieldFans {
    double field = 0;
    std::optional<Vec3> reference;  // the primary wavelength's chief ray in the image plane
    std::vector<RayFan> fans;       // one per wavelength, in the order given
};

struct RayFans {
    double image_z = 0;         // system z
    double primary_nm = 0;      // the reference chief ray's wavelength
    std::vector<double> pupil;  // the normalised stop coordinates, -1 to 1
    std::vector<FieldFans> fields;
};

RayFans ray_fans(const OpticalSystem& system, const FirstOrder& first_order,
                 const RayFanOptions& options);

// What a RayFans holds: transverse ray errors (ray_fans) in lengths, or OPD (opd_fans.h) in
// waves; the report and the figure say which.
enum class FanQuantity { TransverseError, Opd };

}  // namespace lenslab
