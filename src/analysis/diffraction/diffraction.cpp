#include "analysis/diffraction/diffraction.h"

#include <algorithm>
#include <stdexcept>

#include "analysis/diffraction/fft_grid.h"
#include "math/constants.h"

namespace lenslab {
namespace {

// The pupil's complex amplitude A·exp(i2πW); returns Σ A, the aberration-free field at the
// reference point (the normalisation of the PSF and of the Strehl ratio).
double fill_pupil_field(const PupilFunction& pupil, FftGrid& field) {
    double amplitude_sum = 0;
    for (int i = 0; i < pupil.size; ++i)
        for (int j = 0; j < pupil.size; ++j) {
            const double a = pupil.amplitude[pupil.index(i, j)];
            if (a == 0) continue;
            field(i, j) = std::polar(a, 2 * kPi * pupil.opd_waves[pupil.index(i, j)]);
            amplitude_sum += a;
        }
    if (!(amplitude_sum > 0)) throw std::invalid_argument("no light passes the pupil");
    return amplitude_sum;
}

}  // namespace

Psf compute_psf(const PupilFunction& pupil) {
    const int m = pupil.size;
    FftGrid field(m);
    const double amplitude_sum = fill_pupil_field(pupil, field);
    // Fraunhofer: the image-plane field is the pupil field's Fourier transform, frequency
    // index k at image coordinate k·λF/padding (Goodman, eq. 4-17 for a converging wave).
    // The guard band's rows are zero: only the pupil's rows need the first pass.
    field.forward_transposed(m / 2 - pupil.samples / 2, pupil.samples);
    Psf psf;
    psf.size = m;
    psf.spacing = pupil.psf_spacing();
    psf.cutoff = pupil.cutoff_frequency();
    psf.intensity.resize(static_cast<size_t>(m) * m);
    const double norm = 1.0 / (amplitude_sum * amplitude_sum);
    // Zero frequency (the reference point) to the grid's centre.
    field.read_centred(psf.intensity.data(),
                       [norm](const std::complex<double>& v) { return std::norm(v) * norm; });
    psf.strehl = *std::max_element(psf.intensity.begin(), psf.intensity.end());
    return psf;
}

double strehl_at_reference(const PupilFunction& pupil) {
    std::complex<double> field = 0;
    double amplitude_sum = 0;
    for (size_t k = 0; k < pupil.amplitude.size(); ++k) {
        const double a = pupil.amplitude[k];
        if (a == 0) continue;
        field += std::polar(a, 2 * kPi * pupil.opd_waves[k]);
        amplitude_sum += a;
    }
    if (!(amplitude_sum > 0)) throw std::invalid_argument("no light passes the pupil");
    return std::norm(field) / (amplitude_sum * amplitude_sum);
}

}  // namespace lenslab
