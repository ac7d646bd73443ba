#pragma once
// The MTF at every field, tangential and sagittal, polychromatic: what `lenslab analyze --mtf`
// reports for each of --fields (Zemax's "FFT MTF").
//
// At each field and wavelength the real-ray wavefront (field_wavefront.h) is transformed to
// its PSF (diffraction.h) with its tilt taken out, and on to its OTF along x and y (from the
// line spread functions, untilted_psf below); the wavelengths' OTFs are summed with their
// weights, each shifted to where its
// PSF lies against the primary wavelength's chief-ray image point (lateral colour and the
// tilt put back as the phase exp(−i2π ν·Δ)): the OTF of the weighted sum of unit-energy PSFs
// (Goodman, Introduction to Fourier Optics, 3rd ed., section 6.3; the shift theorem). The MTF
// is its modulus. Tangential: frequencies along y (the field's direction); sagittal: along x.
// The diffraction limit beside it is the weighted sum of each wavelength's aberration-free
// MTF at the paraxial working F-number.

#include <complex>
#include <string>
#include <vector>

#include "analysis/diffraction/diffraction.h"
#include "analysis/diffraction/field_wavefront.h"

namespace lenslab {

struct FieldMtfOptions {
    std::vector<double> fields{0.0};  // as FirstOrderOptions::fields (y)
    std::vector<double> wavelengths;  // nm; empty: the first-order data's; the first-order
                                      // data's wavelength is the primary
    std::vector<double> weights;      // one per wavelength; empty: equal
    std::vector<double> frequencies;  // cycles per unit length
    // Rays across the pupil (the FFT grid is twice that) to start with; raised for a wavefront
    // whose phase changes by more than a quarter wave between samples, up to 512.
    int samples = 64;
    // false: keep `samples` whatever the phase steps (the optimiser's operands, whose finite
    // differences a sampling that changed between two designs would break).
    bool resolve = true;
    double image_z = 0;  // the image plane (system z)
    double nm_per_length_unit = 1e6;
};

struct FieldMtf {
    double field = 0;
    std::vector<double> tangential, sagittal;  // at the options' frequencies; empty on error
    std::string error;                         // why the field could not be measured
    int samples = 0;                           // rays across the pupil, the most of any wavelength
    double max_step_waves = 0;                 // field_wavefront.h, the most of any wavelength
    std::string warning;                       // set when the sampling could not resolve the phase
};

struct FieldMtfs {
    double image_z = 0;
    std::vector<double> frequencies, diffraction_limit;
    std::vector<FieldMtf> fields;
};

// Throws std::invalid_argument for bad sampling or weights, SceneError through a
// gradient-index lens. A field whose chief ray does not pass at some wavelength gets its error.
FieldMtfs field_mtfs(const OpticalSystem& system, const FirstOrder& first_order,
                     const FieldMtfOptions& options);

// The MTF at one frequency as the image plane moves along the axis: field_mtfs at
// options.image_z + each shift (system z). fields[k].tangential[n] and .sagittal[n] are at
// shifts[n]; a field that cannot be measured at some plane gets that plane's error.
struct ThroughFocusMtf {
    double frequency = 0, image_z = 0;
    std::vector<double> shifts;
    std::vector<FieldMtf> fields;
};
ThroughFocusMtf through_focus_mtf(const OpticalSystem& system, const FirstOrder& first_order,
                                  FieldMtfOptions options, double frequency,
                                  const std::vector<double>& shifts);

// The PSF of `pupil` with its wavefront tilt (the least-squares plane) taken out, which keeps
// it in the middle of its grid, and where that tilt put it: a tilt W = t·x moves the PSF to
// x = 2 t λN (diffraction.h). Its OTF along x (sagittal) or y (tangential) is the Fourier
// transform of its line spread function (the PSF summed across the other direction), taken
// at exactly the frequency asked: the Nyquist-sampled PSF's transform needs no interpolation,
// which a strongly aberrated PSF's quickly falling OTF would not survive. Phases are about the
// pupil's reference point after the tilt: the pupil's own OTF is otf(ν)·exp(−i2π ν·shift).
struct UntiltedPsf {
    Psf psf;
    std::vector<double> spread_x, spread_y;  // Σ over rows (a function of x), Σ over columns
    double shift_x = 0, shift_y = 0;

    std::complex<double> otf_along_x(double fx) const;
    std::complex<double> otf_along_y(double fy) const;
};
UntiltedPsf untilted_psf(const PupilFunction& pupil);

}  // namespace lenslab
