// The optical transfer function and what is read off it: MTF cuts, the diffraction limit and
// the encircled energy.

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "analysis/diffraction/diffraction.h"
#include "analysis/diffraction/fft_grid.h"
#include "math/constants.h"

namespace lenslab {

OpticalTransfer compute_otf(const Psf& psf) {
    const int m = psf.size;
    FftGrid grid(m);
    // The reference point to index 0, so the OTF's phase is measured about it.
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j) grid((i + m / 2) % m, (j + m / 2) % m) = psf.at(i, j);
    grid.forward_transposed();
    // The zero frequency holds Σ PSF, real and positive.
    const double zero_frequency = grid(0, 0).real();
    if (!(zero_frequency > 0)) throw std::invalid_argument("the PSF holds no energy");
    OpticalTransfer otf;
    otf.size = m;
    otf.spacing = 1.0 / (m * psf.spacing);
    otf.cutoff = psf.cutoff;
    otf.intensity_scale = zero_frequency / (static_cast<double>(m) * m);
    otf.values.resize(static_cast<size_t>(m) * m);
    const double norm = 1.0 / zero_frequency;
    grid.read_centred(otf.values.data(),
                      [norm](const std::complex<double>& v) { return v * norm; });
    return otf;
}

namespace {

// Bilinear interpolation of f(at(i, j)) at (fx, fy); T{} beyond the grid.
template <class T, class F>
T interpolate_otf(const OpticalTransfer& otf, double fx, double fy, F f) {
    const int size = otf.size;
    const double u = fx / otf.spacing + size / 2, v = fy / otf.spacing + size / 2;
    if (!(u >= 0 && v >= 0 && u <= size - 1 && v <= size - 1)) return T{};
    const int j = std::min(static_cast<int>(u), size - 2),
              i = std::min(static_cast<int>(v), size - 2);
    const double tu = u - j, tv = v - i;
    return (1 - tv) * ((1 - tu) * f(otf.at(i, j)) + tu * f(otf.at(i, j + 1))) +
           tv * ((1 - tu) * f(otf.at(i + 1, j)) + tu * f(otf.at(i + 1, j + 1)));
}

}  // namespace

double OpticalTransfer::modulation(double fx, double fy) const {
    return interpolate_otf<double>(*this, fx, fy,
                                   [](const std::complex<double>& v) { return std::abs(v); });
}

std::complex<double> OpticalTransfer::value(double fx, double fy) const {
    return interpolate_otf<std::complex<double>>(*this, fx, fy,
                                                 [](const std::complex<double>& v) { return v; });
}

MtfCurves mtf_curves(const OpticalTransfer& otf, const std::vector<double>& frequencies) {
    MtfCurves c;
    c.frequencies = frequencies;
    for (double f : frequencies) {
        c.tangential.push_back(otf.modulation(0, f));
        c.sagittal.push_back(otf.modulation(f, 0));
        c.diffraction_limit.push_back(diffraction_limited_mtf(f, otf.cutoff));
    }
    return c;
}

double diffraction_limited_mtf(double frequency, double cutoff) {
    const double s = std::abs(frequency) / cutoff;
    if (s >= 1) return 0;
    const double phi = std::acos(s);
    return 2 / kPi * (phi - std::cos(phi) * std::sin(phi));
}

namespace {

// Re OTF gathered by |ν|: the integer |index|² of each sample over the OTF's support (the
// imaginary parts cancel between ν and -ν). What a circularly symmetric integral needs.
struct RadialOtf {
    double at_zero = 0;
    std::vector<double> frequency, weight;
};

RadialOtf gather_radial_otf(const OpticalTransfer& otf) {
    const int half = otf.size / 2;
    const int reach = std::min(half, static_cast<int>(std::ceil(otf.cutoff / otf.spacing)) + 1);
    std::vector<double> by_squared_index(static_cast<size_t>(2 * reach * reach) + 1, 0.0);
    for (int di = -reach; di <= reach; ++di)
        for (int dj = -reach; dj <= reach; ++dj) {
            if (half + di >= otf.size || half + dj >= otf.size) continue;
            by_squared_index[static_cast<size_t>(di * di + dj * dj)] +=
                otf.at(half + di, half + dj).real();
        }
    RadialOtf radial;
    radial.at_zero = by_squared_index[0];
    for (size_t k = 1; k < by_squared_index.size(); ++k) {
        if (by_squared_index[k] == 0) continue;
        radial.frequency.push_back(std::sqrt(static_cast<double>(k)) * otf.spacing);
        radial.weight.push_back(by_squared_index[k]);
    }
    return radial;
}

}  // namespace

std::vector<double> encircled_energy(const OpticalTransfer& otf, const std::vector<double>& radii) {
    const RadialOtf radial = gather_radial_otf(otf);
    std::vector<double> energy;
    energy.reserve(radii.size());
    for (double r : radii) {
        // E(r) = Σ OTF(ν) · r J1(2π r ν)/ν · Δν², the ν → 0 term being π r².
        double e = radial.at_zero * kPi * r * r;
        for (size_t k = 0; k < radial.weight.size(); ++k) {
            const double nu = radial.frequency[k];
            e += radial.weight[k] * r * std::cyl_bessel_j(1.0, 2 * kPi * r * nu) / nu;
        }
        energy.push_back(e * otf.spacing * otf.spacing);
    }
    return energy;
}

std::vector<double> radial_profile(const OpticalTransfer& otf, const std::vector<double>& radii) {
    const RadialOtf radial = gather_radial_otf(otf);
    std::vector<double> profile;
    profile.reserve(radii.size());
    for (double r : radii) {
        double sum = radial.at_zero;
        for (size_t k = 0; k < radial.weight.size(); ++k)
            sum += radial.weight[k] * std::cyl_bessel_j(0.0, 2 * kPi * r * radial.frequency[k]);
        profile.push_back(sum * otf.intensity_scale);
    }
    return profile;
}

}  // namespace lenslab
