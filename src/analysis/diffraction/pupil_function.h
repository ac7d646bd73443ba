#pragma once
// A sampled pupil function: the complex amplitude A·exp(i 2π W) over the exit pupil, with A
// the transmitted amplitude and W the wavefront aberration (optical path difference against
// the reference sphere) in waves. It is what the diffraction figures (diffraction.h)
// transform.
//
// Sampling: `samples` points across the pupil's diameter, centred in a square grid of
// size = samples × padding points a side; the grid beyond the pupil (the guard band) is zero.
// The grid's extent in the pupil sets the PSF's sample spacing, λ·F/padding, so padding ≥ 2
// samples the PSF at or above its Nyquist rate (its spectrum, the OTF, reaches 1/(λF)).
// Sample (i, j) sits at normalised pupil coordinates
//   x = (j - size/2 + 0.5) / (samples/2),  y = (i - size/2 + 0.5) / (samples/2),
// so the pupil (x² + y² ≤ 1) is symmetric about the grid's centre; y is the meridional
// direction, as in the optical system (optical_system.h).

#include <functional>
#include <vector>

namespace lenslab {

struct PupilSampling {
    int samples = 128;  // points across the pupil diameter (even)
    int padding = 2;    // grid size / samples; ≥ 2 for a Nyquist-sampled PSF
};

struct PupilFunction {
    int samples = 0;  // across the pupil diameter
    int size = 0;     // grid points a side: samples × padding
    // Wavelength in the system's length unit (mm for lens prescriptions), and the image-space
    // F-number: together they set the image scale (psf_spacing, cutoff_frequency).
    double wavelength = 0;
    double f_number = 0;
    std::vector<double> amplitude;  // size × size, row-major (row i: y, column j: x)
    std::vector<double> opd_waves;  // same layout; meaningful where amplitude > 0

    int padding() const { return size / samples; }
    size_t index(int i, int j) const { return static_cast<size_t>(i) * size + j; }
    // Normalised pupil coordinate of grid column (or row) j; 1 is the pupil's rim.
    double coordinate(int j) const { return (j - size / 2 + 0.5) / (0.5 * samples); }
    // Distance between PSF samples in the image plane: λ·F/padding.
    double psf_spacing() const { return wavelength * f_number / padding(); }
    // Incoherent cutoff frequency 1/(λF), cycles per unit length.
    double cutoff_frequency() const { return 1.0 / (wavelength * f_number); }
};

// A circular pupil with the wavefront `opd_waves(x, y)` over normalised pupil coordinates
// (x² + y² ≤ 1) and amplitude exp(-apodisation·ρ²) inside (0: uniform; Zemax's Gaussian
// apodisation factor), 0 outside. Throws std::invalid_argument for odd or non-positive
// samples, padding < 2, or a non-positive wavelength or F-number.
PupilFunction make_pupil(const PupilSampling& sampling, double wavelength, double f_number,
                         const std::function<double(double x, double y)>& opd_waves,
                         double apodisation = 0);

// The least-squares plane W ≈ a + t_x·x + t_y·y through the passing samples (each alike),
// taken out of the wavefront: the tilt that moves the PSF to (2 t_x λN, 2 t_y λN)
// (diffraction.h). Returns (t_x, t_y) in waves per unit of normalised pupil; throws
// std::invalid_argument when fewer than three samples pass.
struct WavefrontTilt {
    double x = 0, y = 0;
};
WavefrontTilt remove_tilt(PupilFunction& pupil);

// RMS of the wavefront over the pupil about its mean (piston removed), weighted by intensity
// (amplitude²), in waves: the σ of the Maréchal approximation S ≈ exp(-(2πσ)²).
double wavefront_rms(const PupilFunction& pupil);

}  // namespace lenslab
