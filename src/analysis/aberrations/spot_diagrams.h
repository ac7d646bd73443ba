#pragma once
// Spot diagrams per field and wavelength, as lens-design programs draw them: for each field
// point and each wavelength the beam aimed through the hexapolar grid of the stop
// (field_beam.h, Zemax's "ray density" = rings), its hits in one image plane, their RMS and
// geometric radii about their centroid (Zemax's default reference), the chief ray's hit and
// the vignetted rays; per field the polychromatic RMS radius of all wavelengths together
// (polychromatic_spot.h) beside the Airy radius 1.22 λ N_w.

#include <optional>
#include <vector>

#include "analysis/aberrations/aberrations.h"
#include "analysis/aberrations/polychromatic_spot.h"
#include "analysis/system/first_order.h"

namespace lenslab {

struct SpotOptions {
    // Angles in degrees (object at infinity) or object heights (finite object).
    std::vector<double> fields{0.0};
    std::vector<double> wavelengths;  // nm; empty: the first-order block's
    std::vector<double> weights;      // one per wavelength; empty: all equal
    int rings = 6;                    // hexapolar rings: 1 + 3 rings (rings + 1) rays per beam
    // The image plane in system z; none: the paraxial image plane of the first-order block.
    std::optional<double> image_z;
};

struct WavelengthSpot {
    double field = 0, wavelength_nm = 0;
    SpotDiagram spot;           // radii about the centroid; NaN when every ray was vignetted
    std::optional<Vec3> chief;  // the chief ray's hit, when it passed
    int rays = 0, vignetted = 0;
    double airy_radius = 0;  // 1.22 λ N_w at this wavelength
};

struct FieldSpots {
    double field = 0;
    PolychromaticSpot polychromatic;
    double airy_radius = 0;             // at the first-order block's (primary) wavelength
    std::vector<WavelengthSpot> spots;  // one per wavelength, in the order given
};

struct SpotDiagrams {
    double image_z = 0;  // system z
    int rings = 0, rays_per_beam = 0;
    double primary_nm = 0;  // the first-order block's wavelength
    double working_f_number = 0;
    std::vector<double> wavelengths, weights;  // weights: one per wavelength, as used
    std::vector<FieldSpots> fields;
};

// Lengths in the system's unit; the Airy radius takes it to be mm (as prescriptions are).
SpotDiagrams spot_diagrams(const OpticalSystem& system, const FirstOrder& first_order,
                           const SpotOptions& options);

// 1 + 3 R (R + 1): the rays of a hexapolar grid of R rings.
int hexapolar_ray_count(int rings);

// 1.22 λ N with λ in nm and the radius in mm: the first dark ring of the Airy pattern.
double airy_radius_mm(double wavelength_nm, double f_number);

}  // namespace lenslab
