#include "analysis/diffraction/field_mtf.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <complex>
#include <optional>
#include <stdexcept>

#include "math/cholesky.h"
#include "math/constants.h"

namespace lenslab {

namespace {

// One wavefront's OTF and where its PSF lies against the primary chief ray's image point.
struct PlacedOtf {
    std::optional<ShiftedOtf> otf;
    double x = 0, y = 0;
    std::string error;
};

}  // namespace

ShiftedOtf untilted_otf(const PupilFunction& pupil) {
    // Least-squares plane W ≈ a + b x + c y over the samples that passed.
    std::vector<double> gram(9, 0.0), rhs(3, 0.0);
    for (int i = 0; i < pupil.size; ++i)
        for (int j = 0; j < pupil.size; ++j) {
            const size_t cell = pupil.index(i, j);
            if (!(pupil.amplitude[cell] > 0)) continue;
            const double basis[3] = {1.0, pupil.coordinate(j), pupil.coordinate(i)};
            for (int a = 0; a < 3; ++a) {
                rhs[a] += basis[a] * pupil.opd_waves[cell];
                for (int b = 0; b < 3; ++b) gram[a * 3 + b] += basis[a] * basis[b];
            }
        }
    const std::optional<std::vector<double>> plane = solve_cholesky(gram, rhs);
    if (!plane) throw std::invalid_argument("too few rays pass to measure the wavefront's tilt");
    PupilFunction flat = pupil;
    for (int i = 0; i < flat.size; ++i)
        for (int j = 0; j < flat.size; ++j)
            flat.opd_waves[flat.index(i, j)] -=
                (*plane)[1] * flat.coordinate(j) + (*plane)[2] * flat.coordinate(i);
    const double scale = 2 * pupil.wavelength * pupil.f_number;
    return {compute_otf(compute_psf(flat)), scale * (*plane)[1], scale * (*plane)[2]};
}

FieldMtfs field_mtfs(const OpticalSystem& system, const FirstOrder& first_order,
                     const FieldMtfOptions& options) {
    const std::vector<double> wavelengths = options.wavelengths.empty()
                                                ? std::vector<double>{first_order.wavelength_nm}
                                                : options.wavelengths;
    std::vector<double> weights = options.weights;
    if (weights.empty()) weights.assign(wavelengths.size(), 1.0);
    if (weights.size() != wavelengths.size())
        throw std::invalid_argument("one weight per wavelength");
    double total = 0;
    for (double w : weights) total += w;
    if (!(total > 0)) throw std::invalid_argument("the wavelengths' weights add up to zero");
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
            const FieldWavefront w = field_wavefront(system, first_order, o);
            p.otf = untilted_otf(w.pupil);
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
        }
        if (field.error.empty()) {
            const double ox = origin->x - origin->otf->shift_x,
                         oy = origin->y - origin->otf->shift_y;
            const auto mtf_along = [&](double fx, double fy) {
                std::complex<double> sum = 0;
                for (size_t k = 0; k < per_field; ++k) {
                    const PlacedOtf& p = placed[f * per_field + k];
                    const double phase = -2 * kPi * (fx * (p.x - ox) + fy * (p.y - oy));
                    sum += weights[k] * p.otf->otf.value(fx, fy) * std::polar(1.0, phase);
                }
                return std::abs(sum) / total;
            };
            for (double nu : options.frequencies) {
                field.tangential.push_back(mtf_along(0, nu));
                field.sagittal.push_back(mtf_along(nu, 0));
            }
        }
        out.fields.push_back(std::move(field));
    }
    return out;
}

}  // namespace lenslab
