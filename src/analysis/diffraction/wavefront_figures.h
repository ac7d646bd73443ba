#pragma once
// The wavefront figures of `lenslab analyze --wavefront` in one call: at each field and
// wavelength the OPD over the exit pupil (field_wavefront.h), its RMS and peak-to-valley, the
// Strehl ratio of its PSF (diffraction.h) and its Zernike coefficients in both orderings
// (zernike.h). A field whose chief ray does not pass gets its message instead of figures, so
// the other fields are still reported.

#include <optional>
#include <string>
#include <vector>

#include "analysis/diffraction/field_wavefront.h"
#include "analysis/diffraction/zernike.h"

namespace lenslab {

struct WavefrontFigureOptions {
    std::vector<double> fields{0.0};  // as FirstOrderOptions::fields (y)
    std::vector<double> wavelengths;  // nm; empty: the first-order data's
    int samples = 64;                 // across the pupil (even)
    int zernike_terms = 37;           // Noll terms; Fringe stops at its 37
    std::optional<double> image_z;    // default: the paraxial image of the first-order data
    bool centroid_reference = false;  // refer_to_centroid: the sphere on the PSF's centroid
    double nm_per_length_unit = 1e6;
};

struct WavefrontFigure {
    double field = 0, wavelength_nm = 0;
    std::optional<FieldWavefront> wavefront;  // none when it could not be measured (error)
    ZernikeFit noll, fringe;
    double rms_tilt_removed_waves =
        0;              // RMS with piston and tilt removed (about the PSF's centroid)
    double strehl = 0;  // the PSF's peak against the aberration-free pupil's
    std::string error;
};

struct WavefrontFigures {
    double image_z = 0;
    bool centroid_reference = false;
    int samples = 0, zernike_terms = 0;
    std::vector<WavefrontFigure> figures;  // each field, each wavelength within it
};

// Throws std::invalid_argument for bad samples or terms (before any ray), SceneError through
// a gradient-index lens.
WavefrontFigures wavefront_figures(const OpticalSystem& system, const FirstOrder& first_order,
                                   const WavefrontFigureOptions& options);

}  // namespace lenslab
