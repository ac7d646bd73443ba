#pragma once
// The polychromatic PSF at every field: what `lenslab analyze --psf` reports per field and
// `--psf-png` draws.
//
// At each field and wavelength the real-ray wavefront (field_wavefront.h, its sampling raised
// until the phase is resolved) is transformed onto one image grid shared by every wavelength
// (matrix_psf.h): centred on the primary wavelength's chief-ray image point, its spacing half
// the shortest wavelength's λN (Nyquist for all), wide enough for the blur the wavefront's
// slopes predict. The wavelengths' PSFs are summed as unit-energy PSFs with their weights
// (each PSF's energy is ∝ (λN)²), normalised so that the aberration-free polychromatic PSF
// peaks at 1: the largest sample is the polychromatic Strehl ratio. Encircled and ensquared
// energy are fractions of the PSF's whole energy (Parseval: light beyond the grid counts as
// outside), about the PSF's centroid.

#include <string>
#include <vector>

#include "analysis/diffraction/diffraction.h"
#include "analysis/diffraction/field_wavefront.h"

namespace lenslab {

// How each wavelength's PSF is found on the grid: the matrix Fourier transform (Fraunhofer,
// fast) or Huygens' wavelets from the reference sphere (huygens_psf.h: exact distances, one
// wavelet per ray and sample, slower).
enum class PsfMethod { Transform, Huygens };

struct FieldPsfOptions {
    PsfMethod method = PsfMethod::Transform;
    std::vector<double> fields{0.0};  // as FirstOrderOptions::fields (y)
    std::vector<double> wavelengths;  // nm; empty: the first-order data's (the primary)
    std::vector<double> weights;      // one per wavelength; empty: equal
    int samples = 64;                 // rays across the pupil to start with
    int size = 64;  // image samples a side, at least (raised for a wide blur; made odd)
    double image_z = 0;
    double nm_per_length_unit = 1e6;
};

struct FieldPsf {
    double field = 0;
    Psf psf;                            // polychromatic; coordinates about the grid's centre
    double centre_x = 0, centre_y = 0;  // the grid's centre in the image plane (system x, y)
    std::vector<double> strehl_per_wavelength;  // each wavelength's peak on the grid
    double centroid_x = 0, centroid_y = 0;      // of the polychromatic PSF, system x, y
    // Radii (and half-widths) from the centroid, out to the grid's edge in eighths, and the
    // fraction of the whole energy within.
    std::vector<double> radii, encircled, ensquared;
    int samples = 0;            // rays across the pupil, the most of any wavelength
    double max_step_waves = 0;  // the most of any wavelength (field_wavefront.h)
    std::string warning, error;
};

// Throws std::invalid_argument for bad weights or sizes; a field that cannot be measured gets
// its error.
std::vector<FieldPsf> field_psfs(const OpticalSystem& system, const FirstOrder& first_order,
                                 const FieldPsfOptions& options);

}  // namespace lenslab
