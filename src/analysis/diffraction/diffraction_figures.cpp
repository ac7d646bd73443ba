#include "analysis/diffraction/diffraction_figures.h"

#include "math/constants.h"

namespace lenslab {

DiffractionFigures diffraction_figures(const OpticalSystem& system, const RayPupilOptions& options,
                                       const std::vector<double>& frequencies,
                                       DiffractionFocus focus) {
    const RayWavefront wavefront(system, options);
    DiffractionFigures f;
    f.wavelength_nm = options.wavelength_nm;
    f.f_number = wavefront.f_number();
    f.aperture_radius = wavefront.aperture_radius();
    f.image_z =
        focus == DiffractionFocus::Best ? wavefront.best_focus_z() : wavefront.paraxial_focus_z();
    const PupilFunction pupil = wavefront.pupil(f.image_z);
    f.wavefront_rms = wavefront_rms(pupil);
    f.psf = compute_psf(pupil);
    f.strehl = f.psf.strehl;
    // v = 3.8317060, the first zero of J1: 1.21967 λN.
    f.airy_radius = 3.8317059702 / kPi * wavefront.wavelength() * wavefront.f_number();
    const OpticalTransfer otf = compute_otf(f.psf);
    f.encircled_energy_at_airy_radius = encircled_energy(otf, {f.airy_radius})[0];
    f.mtf =
        mtf_curves(otf, frequencies.empty() ? default_mtf_frequencies(otf.cutoff) : frequencies);
    return f;
}

std::vector<double> default_mtf_frequencies(double cutoff, int count) {
    std::vector<double> out;
    for (int k = 1; k <= count; ++k) out.push_back(cutoff * k / count);
    return out;
}

}  // namespace lenslab
