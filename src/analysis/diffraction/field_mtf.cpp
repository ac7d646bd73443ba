#include "analysis/diffraction/field_mtf.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "analysis/diffraction/weighted_wavelengths.h"
#include "math/constants.h"

namespace lenslab {

namespace {

// One wavefront's OTF and where its PSF lies against the primary chief ray's image point.
struct PlacedOtf {
    std::optional<UntiltedPsf> otf;
    double x = 0, y = 0;
    int samples = 0;
    double max_step_waves = 0;
    std::string error;
};

}  // namespace

namespace {

std::complex<double> line_spread_transform(const Psf& psf, const std::vector<double>& spread,
                                           double frequency) {
    std::complex<double> sum = 0;
    double total = 0;
    for (int k = 0; k < psf.size; ++k) {
        sum += spread[k] * std::polar(1.0, -2 * kPi * frequency * psf.coordinate(k));
        total += spread[k];
    }
    return sum / total;
}

}  // namespace

std::complex<double> UntiltedPsf::otf_along_x(double fx) const {
    return line_spread_transform(psf, spread_x, fx);
}

std::complex<double> UntiltedPsf::otf_along_y(double fy) const {
    return line_spread_transform(psf, spread_y, fy);
}

UntiltedPsf untilted_psf(const PupilFunction& pupil) {
    PupilFunction flat = pupil;
    const WavefrontTilt tilt = remove_tilt(flat);
    const double scale = 2 * pupil.wavelength * pupil.f_number;
    UntiltedPsf out;
    out.psf = compute_psf(flat);
    out.spread_x.assign(static_cast<size_t>(out.psf.size), 0.0);
    out.spread_y.assign(static_cast<size_t>(out.psf.size), 0.0);
    for (int i = 0; i < out.psf.size; ++i)
        for (int j = 0; j < out.psf.size; ++j) {
            out.spread_x[j] += out.psf.at(i, j);
            out.spread_y[i] += out.psf.at(i, j);
        }
    out.shift_x = scale * tilt.x;
    out.shift_y = scale * tilt.y;
    return out;
}

FieldMtfs field_mtfs(const OpticalSystem& system, const FirstOrder& first_order,
                     const FieldMtfOptions& options) {
    const WeightedWavelengths chosen =
        weighted_wavelengths(first_order, options.wavelengths, options.weights);
    const std::vector<double>& wavelengths = chosen.nm;
    const std::vector<double>& weights = chosen.weights;
    const double total = chosen.total;
    make_pupil({options.samples, 2}, 1, 1, [](double, double) { return 0.0; });

    FieldMtfs out;
    out.image_z = options.image_z;
    out.frequencies = options.frequencies;
    for (double f : options.frequencies) {
        double limit = 0;
        for (size_t k = 0; k < wavelengths.size(); ++k) {
            const double lambda = wavelengths[k] / options.nm_per_length_unit;
            limit += weights[k] *
                     diffraction_limited_mtf(f, 1.0 / (lambda * first_order.working_f_number));
        }
        out.diffraction_limit.push_back(limit / total);
    }

    // Every (field, wavelength) apart: each is its own beam, its own FFTs.
    const size_t per_field = wavelengths.size();
    std::vector<PlacedOtf> placed(options.fields.size() * per_field);
    tbb::parallel_for(size_t{0}, placed.size(), [&](size_t n) {
        FieldWavefrontOptions o;
        o.field = options.fields[n / per_field];
        o.wavelength_nm = wavelengths[n % per_field];
        o.sampling = {options.samples, 2};
        o.image_z = options.image_z;
        o.nm_per_length_unit = options.nm_per_length_unit;
        PlacedOtf& p = placed[n];
        try {
            const FieldWavefront w = options.resolve
                                         ? resolved_field_wavefront(system, first_order, o)
                                         : field_wavefront(system, first_order, o);
            p.samples = w.pupil.samples;
            p.max_step_waves = w.max_step_waves;
            p.otf = untilted_psf(w.pupil);
            p.x = w.reference.x + p.otf->shift_x;
            p.y = w.reference.y + p.otf->shift_y;
        } catch (const std::invalid_argument& e) {
            p.error = e.what();
        }
    });
    // The common origin: the primary wavelength's chief ray (the middle one when several, as
    // the first-order data's), else the first wavelength measured.
    for (size_t f = 0; f < options.fields.size(); ++f) {
        FieldMtf field;
        field.field = options.fields[f];
        const PlacedOtf* origin = nullptr;
        for (size_t k = 0; k < per_field; ++k) {
            const PlacedOtf& p = placed[f * per_field + k];
            if (!p.otf) {
                field.error = p.error;
                break;
            }
            if (!origin || wavelengths[k] == first_order.wavelength_nm) origin = &p;
            field.samples = std::max(field.samples, p.samples);
            field.max_step_waves = std::max(field.max_step_waves, p.max_step_waves);
        }
        if (field.max_step_waves > kAliasingStepWaves) {
            char text[200];
            std::snprintf(text, sizeof text,
                          "the wavefront changes by %.2f waves between neighbouring samples even "
                          "at %d across the pupil: the MTF is unreliable",
                          field.max_step_waves, field.samples);
            field.warning = text;
        }
        if (field.error.empty()) {
            const double ox = origin->x - origin->otf->shift_x,
                         oy = origin->y - origin->otf->shift_y;
            // Σ w·OTF(ν)·exp(−i2π ν·Δ) along one axis; `along_y` picks the tangential cut.
            const auto mtf_along = [&](double nu, bool along_y) {
                std::complex<double> sum = 0;
                for (size_t k = 0; k < per_field; ++k) {
                    const PlacedOtf& p = placed[f * per_field + k];
                    const double offset = along_y ? p.y - oy : p.x - ox;
                    const std::complex<double> otf =
                        along_y ? p.otf->otf_along_y(nu) : p.otf->otf_along_x(nu);
                    sum += weights[k] * otf * std::polar(1.0, -2 * kPi * nu * offset);
                }
                return std::abs(sum) / total;
            };
            for (double nu : options.frequencies) {
                field.tangential.push_back(mtf_along(nu, true));
                field.sagittal.push_back(mtf_along(nu, false));
            }
        }
        out.fields.push_back(std::move(field));
    }
    return out;
}

ThroughFocusMtf through_focus_mtf(const OpticalSystem& system, const FirstOrder& first_order,
                                  FieldMtfOptions options, double frequency,
                                  const std::vector<double>& shifts) {
    ThroughFocusMtf out;
    out.frequency = frequency;
    out.image_z = options.image_z;
    out.shifts = shifts;
    for (double field : options.fields) out.fields.push_back({field, {}, {}, {}, 0, 0, {}});
    options.frequencies = {frequency};
    for (double shift : shifts) {
        FieldMtfOptions at = options;
        at.image_z = out.image_z + shift;
        const FieldMtfs m = field_mtfs(system, first_order, at);
        for (size_t k = 0; k < m.fields.size(); ++k) {
            FieldMtf& f = out.fields[k];
            const FieldMtf& here = m.fields[k];
            if (!here.error.empty() && f.error.empty()) f.error = here.error;
            if (!here.warning.empty() && f.warning.empty()) f.warning = here.warning;
            f.samples = std::max(f.samples, here.samples);
            f.max_step_waves = std::max(f.max_step_waves, here.max_step_waves);
            f.tangential.push_back(here.error.empty() ? here.tangential[0] : 0.0);
            f.sagittal.push_back(here.error.empty() ? here.sagittal[0] : 0.0);
        }
    }
    for (FieldMtf& f : out.fields)
        if (!f.error.empty()) f.tangential.clear(), f.sagittal.clear();
    return out;
}

}  // namespace lenslab
