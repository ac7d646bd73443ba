#include "analysis/diffraction/wavefront_figures.h"

#include <algorithm>
#include <stdexcept>

#include "analysis/diffraction/diffraction.h"

namespace lenslab {

namespace {

constexpr int kFringeTermCount = 37;

WavefrontFigure measure_wavefront(const OpticalSystem& system, const FirstOrder& first_order,
                                  const FieldWavefrontOptions& options, int terms,
                                  bool centroid_reference) {
    WavefrontFigure f;
    f.field = options.field;
    f.wavelength_nm = options.wavelength_nm;
    try {
        f.wavefront = field_wavefront(system, first_order, options);
        if (centroid_reference) refer_to_centroid(*f.wavefront);
        const PupilFunction& pupil = f.wavefront->pupil;
        f.noll = fit_zernike(pupil, ZernikeOrdering::Noll, terms);
        f.fringe = fit_zernike(pupil, ZernikeOrdering::Fringe, std::min(terms, kFringeTermCount));
        f.rms_tilt_removed_waves = fit_zernike(pupil, ZernikeOrdering::Noll, 3).residual_rms;
        f.strehl = compute_psf(pupil).strehl;
    } catch (const std::invalid_argument& e) {
        f.wavefront.reset();
        f.error = e.what();
    }
    return f;
}

}  // namespace

WavefrontFigures wavefront_figures(const OpticalSystem& system, const FirstOrder& first_order,
                                   const WavefrontFigureOptions& options) {
    // Checked here so a bad request fails whole rather than as a message per field.
    make_pupil({options.samples, 2}, 1, 1, [](double, double) { return 0.0; });
    zernike_index(ZernikeOrdering::Noll, options.zernike_terms);
    WavefrontFigures out;
    out.image_z = options.image_z.value_or(system.last_vertex() + first_order.image_position);
    out.samples = options.samples;
    out.centroid_reference = options.centroid_reference;
    out.zernike_terms = options.zernike_terms;
    const std::vector<double> wavelengths = options.wavelengths.empty()
                                                ? std::vector<double>{first_order.wavelength_nm}
                                                : options.wavelengths;
    for (double field : options.fields)
        for (double nm : wavelengths) {
            FieldWavefrontOptions o;
            o.field = field;
            o.wavelength_nm = nm;
            o.sampling = {options.samples, 2};
            o.image_z = out.image_z;
            o.nm_per_length_unit = options.nm_per_length_unit;
            out.figures.push_back(measure_wavefront(system, first_order, o, options.zernike_terms,
                                                    options.centroid_reference));
        }
    return out;
}

}  // namespace lenslab
