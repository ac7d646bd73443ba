#pragma once
// A sequential lens prescription as lens design programs write it (Zemax .zmx, CODE V .seq):
// the surfaces from the object to the image, each with the medium that follows it, and the
// system data that go with them (wavelengths, fields, aperture). The readers fill it in the
// file's own units; lens_group_from_prescription turns it into a lenslab lens_group.

#include <string>
#include <vector>

#include "lensfile/lens_file_error.h"

namespace lenslab {

struct LensFileSurface {
    int line = 0;            // where the surface starts in the file
    int radius_line = 0;     // where its curvature or radius was given (0: not given)
    int glass_line = 0;      // where its glass was given
    double radius = 0.0;     // vertex radius of curvature, signed; 0: flat
    double thickness = 0.0;  // axial distance to the next surface (may be infinite: object)
    double conic = 0.0;
    // Even asphere terms: r^2, r^4, r^6, ... (index 0 is the r^2 term); of a toroid, its y
    // curve's y^2, y^4, ...
    std::vector<double> even_terms;
    // A surface not of revolution: "biconic" (Zemax BICONICX: radius and conic above are the
    // y section's, radius_x and conic_x the x section's, 0 flat), "toroidal" (Zemax
    // TOROIDAL: the y curve turned about the radius of rotation, 0 none), "zernike" (Zemax
    // SZERNSAG: the even asphere plus Noll Zernike terms) or "xy_polynomial" (Zemax XPOLYNOM:
    // the conic plus terms in x, y, x^2, xy, ...). Empty: none of them.
    std::string anamorphic;
    double radius_x = 0.0, conic_x = 0.0, radius_of_rotation = 0.0;
    // Zemax's extra data (XDAT 1, 2, ...): of SZERNSAG and XPOLYNOM, the number of terms, the
    // normalisation radius, then the terms.
    std::vector<double> extra_data;
    int extra_data_line = 0;
    std::string glass;  // the medium after the surface; empty: air
    // A model glass given by its index and Abbe number (Zemax ___BLANK, a CODE V glass code
    // such as 517642 or 517000.520000), when glass is empty.
    double model_nd = 0.0, model_vd = 0.0;
    double semi_diameter = 0.0;  // 0: not given
    // The radius of a central obscuration on the surface (CODE V CIR OBS, Zemax OBSC): light
    // that meets the surface nearer the axis is blocked. 0: none. Read, not yet used.
    double obscuration_semi_diameter = 0.0;
    bool stop = false;
    // A mirror (Zemax GLAS MIRROR, CODE V REFL): light turns back along the axis, the
    // thicknesses after it negative as the file writes them; the medium stays the one before.
    bool mirror = false;
    double hole_semi_diameter = 0.0;  // a central hole in a mirror (CODE V CIR HOL)
    // A mirror's tilt about the local x or y axis (degrees, right-handed): a fold, the axis
    // frame turning by twice the tilt behind it.
    double tilt_x = 0.0, tilt_y = 0.0;
    // A Zemax coordinate break (TYPE COORDBRK): PARM 1-6, decentre x and y, tilts about x, y
    // and z (degrees), the order flag. Represented: the fold around a mirror, and a pair
    // around an element that moves it (element_motion).
    bool coordinate_break = false;
    double break_parameters[6] = {0, 0, 0, 0, 0, 0};
    int break_line = 0;
    // The decentre (x, y) and tilts (about x, y, z; degrees) of the element that starts at this
    // surface: a coordinate break of order 0 before it and its inverse after it (Zemax's tilted
    // element), or CODE V's element decentre. Zero: none.
    double element_motion[5] = {0, 0, 0, 0, 0};
};

struct LensFilePrescription {
    std::string file;    // as named to the reader, for messages
    std::string format;  // "zmx" or "seq"
    std::string title;
    double unit_mm = 1.0;                 // millimetres per length unit of the file
    std::vector<std::string> catalogues;  // glass catalogues the file names (Zemax GCAT)
    std::vector<double> wavelengths_nm;
    int primary_wavelength = 0;  // index into wavelengths_nm
    // "angle" (degrees), "object_height", "paraxial_image_height", "real_image_height".
    std::string field_type = "angle";
    std::vector<double> fields_x, fields_y;
    // CODE V's vignetting factors per y field (VUY, VLY): the fraction of the pupil cut off at
    // the top and the bottom; empty: none.
    std::vector<double> vignetting_upper, vignetting_lower;
    // "entrance_pupil_diameter", "f_number" (image space), "object_na"; empty: none given.
    std::string aperture_type;
    // How the file's program aims real rays (Zemax RAIM): "paraxial" (at the paraxial
    // entrance pupil), "real" (through the stop), "" (not said).
    std::string ray_aiming;
    double aperture = 0.0;
    // Object, optical surfaces, image, in order.
    std::vector<LensFileSurface> surfaces;
    // A zoom's configurations (Zemax's multi-configuration editor, MNUM and THIC records): how
    // many, the one the surfaces above hold (the file's active one), and each configuration's
    // surface thicknesses.
    int configurations = 1, active_configuration = 1;
    struct ConfigurationThickness {
        int surface = 0, configuration = 0, line = 0;
        double value = 0;
    };
    std::vector<ConfigurationThickness> configuration_thicknesses;
    std::vector<LensFileWarning> warnings;
};

}  // namespace lenslab
