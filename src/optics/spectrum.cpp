#include "optics/spectrum.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <numbers>
#include <vector>

#include "optics/cie_tables.h"
#include "util/format_number.h"

namespace lenslab {

namespace {

double table_lookup(const double* table, int count, double start, double nm) {
    const double x = (nm - start) / cie::kStepNm;
    if (!(x >= 0.0) || x > count - 1) return 0.0;
    const int i = std::min(static_cast<int>(x), count - 2);
    const double f = x - i;
    return table[i] * (1.0 - f) + table[i + 1] * f;
}

double d65_raw(double nm) { return table_lookup(cie::kD65, cie::kD65Count, cie::kD65StartNm, nm); }

// Integral over the visible range of f(nm), midpoint rule on a 0.1 nm grid: the same
// integral (of the linearly interpolated tables, with sharp band edges) that the Monte
// Carlo wavelength estimates converge to, so calibrations and estimates agree.
template <class F>
double integrate(F f) {
    constexpr double step = 0.1;
    double s = 0.0;
    for (double nm = kLambdaMinNm + 0.5 * step; nm < kLambdaMaxNm; nm += step) s += f(nm);
    return s * step;
}

// Constants derived once from the tables: D65 scaled to Y = 1, and the 3x3 matrix taking
// band weights to the linear sRGB of the banded spectrum lit by (or multiplied with) D65.
struct Calibration {
    double d65_scale = 1.0;     // D65 * d65_scale has Y = 1
    double d65_power = 1.0;     // int D65 * d65_scale over the visible range
    Rgb white{1, 1, 1};         // linear sRGB of that D65 before white balancing
    double inverse[3][3] = {};  // band weights from linear sRGB
    BandColour d65_bands;       // band colours of D65 * d65_scale

    // The tabulated D65 is a hair off the sRGB white point; dividing by its colour makes
    // D65 exactly [1, 1, 1], so greys round-trip exactly.
    Rgb balanced(const Vec3& xyz) const {
        const Rgb c = xyz_to_linear_srgb(xyz);
        return {c.r / white.r, c.g / white.g, c.b / white.b};
    }

    Calibration() {
        const double y_integral = cie_y_integral();
        d65_scale =
            y_integral / integrate([](double nm) { return d65_raw(nm) * cie_xyz_bar(nm).y; });
        d65_power = integrate([&](double nm) { return d65_raw(nm) * d65_scale; });
        Vec3 white_xyz;
        for (int c = 0; c < 3; ++c) {
            white_xyz[c] =
                integrate([&](double nm) { return d65_raw(nm) * d65_scale * cie_xyz_bar(nm)[c]; }) /
                y_integral;
        }
        white = xyz_to_linear_srgb(white_xyz);
        double m[3][3];
        for (int band = 0; band < 3; ++band) {
            Vec3 xyz;
            for (int c = 0; c < 3; ++c) {
                xyz[c] = integrate([&](double nm) {
                             return band_of(nm) == band
                                        ? d65_raw(nm) * d65_scale * cie_xyz_bar(nm)[c]
                                        : 0.0;
                         }) /
                         y_integral;
            }
            const Rgb rgb = balanced(xyz);
            d65_bands.band[band] = rgb;
            m[0][band] = rgb.r;
            m[1][band] = rgb.g;
            m[2][band] = rgb.b;
        }
        const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
        for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 3; ++c) {
                const int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
                inverse[r][c] = (m[r1][c1] * m[r2][c2] - m[r1][c2] * m[r2][c1]) / det;
            }
        }
    }

    std::array<double, 3> weights(const Rgb& rgb, double max_weight) const {
        std::array<double, 3> w{};
        for (int b = 0; b < 3; ++b) {
            w[b] = std::clamp(inverse[b][0] * rgb.r + inverse[b][1] * rgb.g + inverse[b][2] * rgb.b,
                              0.0, max_weight);
        }
        return w;
    }
};

const Calibration& calibration() {
    static const Calibration c;
    return c;
}

class BandSpectrum final : public Spectrum {
public:
    BandSpectrum(std::array<double, 3> w, bool lit) : m_w(w), m_lit(lit) {}
    double eval(double nm) const override {
        if (nm < kLambdaMinNm || nm > kLambdaMaxNm) return 0.0;
        const double band = m_w[band_of(nm)];
        return m_lit ? band * d65_raw(nm) * calibration().d65_scale : band;
    }

private:
    std::array<double, 3> m_w;
    bool m_lit;
};

// A spectrum given by a function, rescaled to D65 white's radiant power.
template <class F>
class PowerNormalised final : public Spectrum {
public:
    explicit PowerNormalised(F f) : m_f(f) {
        // The same integral as radiant_power() and spectrum_to_rgb(), so the light's power
        // is what the scene says whatever the spectrum's shape (a coarser sum here once made
        // a 0.05 nm laser line 5.7 times too bright).
        const double power = integrate(m_f);
        m_scale = power > 0 ? calibration().d65_power / power : 0.0;
    }
    double eval(double nm) const override {
        return nm < kLambdaMinNm || nm > kLambdaMaxNm ? 0.0 : m_f(nm) * m_scale;
    }

private:
    F m_f;
    double m_scale = 1.0;
};

template <class F>
SpectrumPtr make_normalised(F f) {
    return std::make_shared<PowerNormalised<F>>(f);
}

}  // namespace

int band_of(double nm) { return nm < 490.0 ? 2 : (nm < 585.0 ? 1 : 0); }

SampledWavelengths SampledWavelengths::sample(double u) {
    SampledWavelengths w;
    const double range = kLambdaMaxNm - kLambdaMinNm;
    for (int i = 0; i < kWavelengthSamples; ++i) {
        double t = u + static_cast<double>(i) / kWavelengthSamples;
        if (t >= 1.0) t -= 1.0;
        w.nm[i] = kLambdaMinNm + t * range;
    }
    return w;
}

SampledWavelengths SampledWavelengths::single(double nm) {
    SampledWavelengths w;
    w.nm.fill(nm);
    return w;
}

Vec3 cie_xyz_bar(double nm) {
    return {table_lookup(cie::kX, cie::kCmfCount, cie::kCmfStartNm, nm),
            table_lookup(cie::kY, cie::kCmfCount, cie::kCmfStartNm, nm),
            table_lookup(cie::kZ, cie::kCmfCount, cie::kCmfStartNm, nm)};
}

double cie_y_integral() {
    static const double integral = integrate([](double nm) { return cie_xyz_bar(nm).y; });
    return integral;
}

Rgb xyz_to_linear_srgb(const Vec3& xyz) {
    // IEC 61966-2-1 (sRGB), D65 white.
    return {3.2404542 * xyz.x - 1.5371385 * xyz.y - 0.4985314 * xyz.z,
            -0.9692660 * xyz.x + 1.8760108 * xyz.y + 0.0415560 * xyz.z,
            0.0556434 * xyz.x - 0.2040259 * xyz.y + 1.0572252 * xyz.z};
}

Rgb sample_to_rgb(double value, double nm, double pdf) {
    return xyz_sample_to_rgb(cie_xyz_bar(nm) * (value / pdf));
}

Rgb xyz_sample_to_rgb(const Vec3& xyz) {
    return calibration().balanced(xyz * (1.0 / cie_y_integral()));
}

double radiant_power(const Spectrum& s) {
    return integrate([&](double nm) { return s.eval(nm); });
}

Vec3 spectrum_xyz(const Spectrum& s) {
    Vec3 xyz;
    for (int c = 0; c < 3; ++c)
        xyz[c] = integrate([&](double nm) { return s.eval(nm) * cie_xyz_bar(nm)[c]; });
    return xyz;
}

Rgb spectrum_to_rgb(const Spectrum& s) { return xyz_sample_to_rgb(spectrum_xyz(s)); }

Rgb to_rgb(const SampledSpectrum& s, const SampledWavelengths& w) {
    Vec3 xyz;
    for (int i = 0; i < kWavelengthSamples; ++i) xyz += cie_xyz_bar(w.nm[i]) * s.v[i];
    return calibration().balanced(
        xyz * (1.0 / (kWavelengthSamples * SampledWavelengths::pdf() * cie_y_integral())));
}

SampledSpectrum Spectrum::sample(const SampledWavelengths& w) const {
    SampledSpectrum s;
    for (int i = 0; i < kWavelengthSamples; ++i) s.v[i] = eval(w.nm[i]);
    return s;
}

double Spectrum::sample_wavelength(double u, double& nm) const {
    std::call_once(m_cdf_once, [this] {
        const int bins = static_cast<int>(kLambdaMaxNm - kLambdaMinNm);
        m_cdf.assign(bins + 1, 0.0);
        for (int b = 0; b < bins; ++b) {
            // Several points per bin so a line narrower than a bin is not missed.
            double v = 0.0;
            for (int k = 0; k < 8; ++k) v += eval(kLambdaMinNm + b + (k + 0.5) / 8.0);
            m_cdf[b + 1] = m_cdf[b] + v / 8.0;
        }
    });
    const double total = m_cdf.back();
    if (total <= 0.0) {
        nm = kLambdaMinNm + u * (kLambdaMaxNm - kLambdaMinNm);
        return SampledWavelengths::pdf();
    }
    const double target = u * total;
    const auto it = std::upper_bound(m_cdf.begin() + 1, m_cdf.end(), target);
    const int b =
        std::min(static_cast<int>(it - m_cdf.begin()) - 1, static_cast<int>(m_cdf.size()) - 2);
    const double in_bin = m_cdf[b + 1] - m_cdf[b];
    nm = kLambdaMinNm + b + (in_bin > 0 ? (target - m_cdf[b]) / in_bin : 0.5);
    return in_bin / total;  // density per nm, constant over this 1 nm bin
}

const BandColour& Spectrum::band_colour() const {
    std::call_once(m_band_once, [this] {
        // spectrum_to_rgb's sum, split by band: the 0.1 nm grid's midpoints never fall on a
        // band edge, so each term lands in exactly one band.
        std::array<Vec3, 3> xyz;
        constexpr double step = 0.1;
        for (double nm = kLambdaMinNm + 0.5 * step; nm < kLambdaMaxNm; nm += step) {
            xyz[band_of(nm)] += cie_xyz_bar(nm) * eval(nm);
        }
        for (int b = 0; b < 3; ++b) {
            m_band_colour.band[b] = calibration().balanced(xyz[b] * (step / cie_y_integral()));
        }
    });
    return m_band_colour;
}

double radiant_watts(const Spectrum& s, double lo_nm, double hi_nm) {
    // The midpoint rule on the grid `integrate` uses (0.1 nm), clipped to [lo, hi], so the
    // bands of a partition sum to the whole and a white light of power P gives P watts.
    constexpr double step = 0.1;
    lo_nm = std::max(lo_nm, kLambdaMinNm);
    hi_nm = std::min(hi_nm, kLambdaMaxNm);
    double sum = 0.0;
    for (double nm = kLambdaMinNm + 0.5 * step; nm < kLambdaMaxNm; nm += step) {
        const double a = std::max(lo_nm, nm - 0.5 * step), b = std::min(hi_nm, nm + 0.5 * step);
        if (b > a) sum += s.eval(nm) * (b - a);
    }
    return sum / calibration().d65_power;
}

SpectrumPtr reflectance_from_rgb(const Rgb& rgb) {
    return std::make_shared<BandSpectrum>(calibration().weights(rgb, 1.0), false);
}

BandWeights reflectance_bands(const Rgb& rgb) { return calibration().weights(rgb, 1.0); }
BandWeights coefficient_bands(const Rgb& rgb) { return calibration().weights(rgb, INFINITY); }

BandColour illuminant_band_colour(const Rgb& rgb) {
    const auto weights = calibration().weights(rgb, INFINITY);
    BandColour c = calibration().d65_bands;
    for (int b = 0; b < 3; ++b) c.band[b] *= weights[b];
    return c;
}

SpectrumPtr illuminant_from_rgb(const Rgb& rgb) {
    return std::make_shared<BandSpectrum>(calibration().weights(rgb, INFINITY), true);
}

SampledSpectrum illuminant_from_rgb(const Rgb& rgb, const SampledWavelengths& w) {
    const auto weights = calibration().weights(rgb, INFINITY);
    SampledSpectrum s;
    for (int i = 0; i < kWavelengthSamples; ++i) {
        s.v[i] = weights[band_of(w.nm[i])] * d65_raw(w.nm[i]) * calibration().d65_scale;
    }
    return s;
}

SpectrumPtr d65_spectrum() { return illuminant_from_rgb(Rgb{1, 1, 1}); }

std::optional<std::string> blackbody_problem(double kelvin) {
    if (kelvin >= kBlackbodyMinK && kelvin <= kBlackbodyMaxK) return std::nullopt;
    return "must be between " + format_number(kBlackbodyMinK) + " and " +
           format_number(kBlackbodyMaxK) + " K";
}

std::optional<std::string> wavelength_problem(double nm) {
    if (nm >= kLambdaMinNm && nm <= kLambdaMaxNm) return std::nullopt;
    return "outside " + format_number(kLambdaMinNm) + " to " + format_number(kLambdaMaxNm) +
           " nm, the range of the CIE tables";
}

SpectrumPtr blackbody_spectrum(double kelvin) {
    // Planck's law, B(l, T) = 2 h c^2 / l^5 / (exp(h c / (l k T)) - 1) (CODATA constants).
    constexpr double h = 6.62607015e-34, c = 299792458.0, k = 1.380649e-23;
    return make_normalised([kelvin](double nm) {
        const double l = nm * 1e-9;
        return 2.0 * h * c * c / std::pow(l, 5) / std::expm1(h * c / (l * k * kelvin));
    });
}

SpectrumPtr illuminant_a_spectrum() {
    // CIE standard illuminant A by its defining formula (CIE 15:2004, eq. 3.1; ISO 11664-2):
    // S(l) = 100 (560 / l)^5 (exp(1.435e7 / (2848 x 560)) - 1) / (exp(1.435e7 / (2848 l)) - 1),
    // l in nm: a blackbody of about 2856 K with the c2 of the old temperature scale.
    return make_normalised([](double nm) {
        constexpr double c2 = 1.435e7, t = 2848.0;
        return std::pow(560.0 / nm, 5) * std::expm1(c2 / (t * 560.0)) / std::expm1(c2 / (t * nm));
    });
}

SpectrumPtr equal_energy_spectrum() {
    return make_normalised([](double) { return 1.0; });
}

const std::vector<NamedSpectrum>& named_spectra() {
    static const std::vector<NamedSpectrum> names{
        {"d65", "CIE daylight D65 (the white of RGB colours)", d65_spectrum},
        {"illuminant_a", "CIE illuminant A (a tungsten lamp, about 2856 K)", illuminant_a_spectrum},
        {"equal_energy", "CIE illuminant E, flat in wavelength", equal_energy_spectrum},
    };
    return names;
}

SpectrumPtr line_spectrum(double centre_nm, double width_nm) {
    // Narrower lines are drawn 0.1 nm wide: the 0.1 nm integration grid then still measures
    // their power exactly, and no glass disperses 0.1 nm visibly.
    const double sigma = std::max(width_nm, 0.1);
    return make_normalised([centre_nm, sigma](double nm) {
        const double x = (nm - centre_nm) / sigma;
        return std::exp(-0.5 * x * x);
    });
}

}  // namespace lenslab
