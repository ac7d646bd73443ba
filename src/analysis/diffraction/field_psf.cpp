#include "analysis/diffraction/field_psf.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "analysis/diffraction/huygens_psf.h"
#include "analysis/diffraction/matrix_psf.h"
#include "analysis/diffraction/weighted_wavelengths.h"

namespace lenslab {

namespace {

constexpr int kLargestPsfGrid = 256;
constexpr int kEnergyRadii = 8;

// The whole energy of a pupil's peak-normalised PSF, ∫ I dA over the image plane, by
// Parseval: (2λN)² ΣA² / (δ² (ΣA)²) with δ = 2/samples the pupil's sample pitch; 4(λN)²/π for
// a full circle (the Airy pattern).
double psf_energy(const PupilFunction& pupil) {
    double sum = 0, squares = 0;
    for (double a : pupil.amplitude) {
        sum += a;
        squares += a * a;
    }
    const double two_lambda_n = 2 * pupil.wavelength * pupil.f_number;
    const double pitch = 2.0 / pupil.samples;
    return two_lambda_n * two_lambda_n * squares / (pitch * pitch * sum * sum);
}

// The fractions of the PSF's energy (`energy`, all of it, on the grid or not) within each
// radius (circle) and half-width (square) of (cx, cy), grid coordinates.
void gather_energy(FieldPsf& f, double cx, double cy, double energy) {
    const Psf& p = f.psf;
    const double total = energy / (p.spacing * p.spacing);  // in samples' units
    const double reach = 0.5 * p.size * p.spacing;
    for (int k = 1; k <= kEnergyRadii; ++k) {
        const double r = reach * k / kEnergyRadii;
        double circle = 0, square = 0;
        for (int i = 0; i < p.size; ++i)
            for (int j = 0; j < p.size; ++j) {
                const double dx = p.coordinate(j) - cx, dy = p.coordinate(i) - cy;
                if (dx * dx + dy * dy <= r * r) circle += p.at(i, j);
                if (std::abs(dx) <= r && std::abs(dy) <= r) square += p.at(i, j);
            }
        f.radii.push_back(r);
        f.encircled.push_back(circle / total);
        f.ensquared.push_back(square / total);
    }
}

}  // namespace

std::vector<FieldPsf> field_psfs(const OpticalSystem& system, const FirstOrder& first_order,
                                 const FieldPsfOptions& options) {
    const WeightedWavelengths chosen =
        weighted_wavelengths(first_order, options.wavelengths, options.weights);
    if (options.size < 8 || options.size > kLargestPsfGrid)
        throw std::invalid_argument("a PSF grid has 8 to 256 samples a side");
    const size_t per_field = chosen.nm.size();
    const double shortest = *std::min_element(chosen.nm.begin(), chosen.nm.end());
    const double spacing =
        0.5 * shortest / options.nm_per_length_unit * first_order.working_f_number;

    // The wavefronts first, every (field, wavelength) in parallel.
    std::vector<std::optional<FieldWavefront>> waves(options.fields.size() * per_field);
    std::vector<std::string> errors(waves.size());
    tbb::parallel_for(size_t{0}, waves.size(), [&](size_t n) {
        FieldWavefrontOptions o;
        o.field = options.fields[n / per_field];
        o.wavelength_nm = chosen.nm[n % per_field];
        o.sampling = {options.samples, 2};
        o.image_z = options.image_z;
        o.nm_per_length_unit = options.nm_per_length_unit;
        try {
            waves[n] = resolved_field_wavefront(system, first_order, o);
        } catch (const std::invalid_argument& e) {
            errors[n] = e.what();
        }
    });

    std::vector<FieldPsf> out;
    for (size_t f = 0; f < options.fields.size(); ++f) {
        FieldPsf field;
        field.field = options.fields[f];
        const FieldWavefront* primary = nullptr;
        double blur = 0;  // the widest geometric blur radius the wavefronts' slopes predict
        for (size_t k = 0; k < per_field; ++k) {
            const std::optional<FieldWavefront>& w = waves[f * per_field + k];
            if (!w) {
                field.error = errors[f * per_field + k];
                break;
            }
            if (!primary || chosen.nm[k] == first_order.wavelength_nm) primary = &*w;
            field.samples = std::max(field.samples, w->pupil.samples);
            field.max_step_waves = std::max(field.max_step_waves, w->max_step_waves);
            // A step s over 2/samples of the pupil is a slope s·samples/2 waves per unit,
            // which moves a ray by twice that times λN (the tilt rule of diffraction.h).
            const double lambda_n = w->pupil.wavelength * w->pupil.f_number;
            blur = std::max(blur, lambda_n * w->max_step_waves * w->pupil.samples);
        }
        if (!field.error.empty()) {
            out.push_back(std::move(field));
            continue;
        }
        field.centre_x = primary->reference.x;
        field.centre_y = primary->reference.y;
        // Lateral colour spreads the wavelengths' PSFs too.
        double spread = 0;
        for (size_t k = 0; k < per_field; ++k) {
            const Vec3& r = waves[f * per_field + k]->reference;
            spread = std::max(spread, std::hypot(r.x - field.centre_x, r.y - field.centre_y));
        }
        const double half_width = std::max(8.0 * spacing * 2, 1.3 * (blur + spread));
        int size = 2 * static_cast<int>(std::ceil(half_width / spacing));
        // Odd: a middle sample on the centre, the grid symmetric about it.
        size = std::clamp(size, options.size, kLargestPsfGrid) | 1;
        if (field.max_step_waves > kAliasingStepWaves || 0.5 * size * spacing < blur + spread) {
            char text[200];
            std::snprintf(text, sizeof text,
                          "the PSF is not resolved (phase steps of %.2f waves at %d rays across, "
                          "or a blur wider than the %d-sample grid): its figures are unreliable",
                          field.max_step_waves, field.samples, size);
            field.warning = text;
        }

        // Σ w I_λ / λ² over Σ w / λ²: unit-energy PSFs, the perfect sum peaking at 1.
        double norm = 0, energy = 0;
        for (size_t k = 0; k < per_field; ++k) {
            const FieldWavefront& w = *waves[f * per_field + k];
            const ImageGrid grid{size, spacing, field.centre_x - w.reference.x,
                                 field.centre_y - w.reference.y};
            const Psf one =
                options.method == PsfMethod::Huygens
                    ? huygens_psf(w, {grid.size, grid.spacing, grid.centre_x, grid.centre_y})
                    : matrix_psf(w.pupil, grid);
            field.strehl_per_wavelength.push_back(one.strehl);
            const double weight = chosen.weights[k] / (chosen.nm[k] * chosen.nm[k]);
            if (field.psf.intensity.empty()) {
                field.psf = one;
                for (double& v : field.psf.intensity) v *= weight;
            } else {
                for (size_t s = 0; s < one.intensity.size(); ++s)
                    field.psf.intensity[s] += weight * one.intensity[s];
            }
            norm += weight;
            energy += weight * psf_energy(w.pupil);
        }
        double cx = 0, cy = 0, total = 0;
        for (int i = 0; i < size; ++i)
            for (int j = 0; j < size; ++j) {
                double& v = field.psf.intensity[static_cast<size_t>(i) * size + j];
                v /= norm;
                cx += v * field.psf.coordinate(j);
                cy += v * field.psf.coordinate(i);
                total += v;
            }
        field.psf.strehl =
            *std::max_element(field.psf.intensity.begin(), field.psf.intensity.end());
        cx /= total;
        cy /= total;
        field.centroid_x = field.centre_x + cx;
        field.centroid_y = field.centre_y + cy;
        gather_energy(field, cx, cy, energy / norm);
        out.push_back(std::move(field));
    }
    return out;
}

}  // namespace lenslab
