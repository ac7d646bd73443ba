#include "optics/smooth_spectrum.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "math/cholesky.h"

namespace lenslab {

namespace {

constexpr double kCentreNm = 595.0, kHalfWidthNm = 235.0;
constexpr double kStepNm = 0.1;  // spectrum_to_rgb's grid (midpoints)

double sigmoid(double y) { return 0.5 + y / (2.0 * std::sqrt(1.0 + y * y)); }
// d sigmoid / dy
double sigmoid_slope(double y) { return 0.5 / std::pow(1.0 + y * y, 1.5); }

// The colour of a unit reflectance at each grid point under D65: rgb(s) = sum s(x_j) B_j.
struct Grid {
    std::vector<double> x;
    std::vector<Rgb> weight;
    Grid() {
        const SpectrumPtr d65 = d65_spectrum();
        for (double nm = kLambdaMinNm + 0.5 * kStepNm; nm < kLambdaMaxNm; nm += kStepNm) {
            x.push_back((nm - kCentreNm) / kHalfWidthNm);
            weight.push_back(xyz_sample_to_rgb(cie_xyz_bar(nm) * (d65->eval(nm) * kStepNm)));
        }
    }
};

const Grid& grid() {
    static const Grid g;
    return g;
}

double polynomial(const std::array<double, 3>& c, double x) { return (c[0] * x + c[1]) * x + c[2]; }

// The colour of the sigmoid spectrum and its derivatives by c0, c1, c2.
void colour_and_jacobian(const std::array<double, 3>& c, Rgb& colour, Rgb jacobian[3]) {
    const Grid& g = grid();
    colour = {};
    for (int k = 0; k < 3; ++k) jacobian[k] = {};
    for (size_t j = 0; j < g.x.size(); ++j) {
        const double x = g.x[j], y = polynomial(c, x);
        colour += g.weight[j] * sigmoid(y);
        const double d = sigmoid_slope(y);
        jacobian[0] += g.weight[j] * (d * x * x);
        jacobian[1] += g.weight[j] * (d * x);
        jacobian[2] += g.weight[j] * d;
    }
}

double channel(const Rgb& c, int i) { return i == 0 ? c.r : (i == 1 ? c.g : c.b); }

// The damped Gauss-Newton step: (J^T J + mu I) delta = -J^T r, symmetric positive definite;
// no step when it is numerically not.
std::array<double, 3> step(const Rgb jacobian[3], const Rgb& residual, double mu) {
    std::vector<double> a(9), b(3);
    for (int p = 0; p < 3; ++p) {
        for (int q = 0; q < 3; ++q) {
            a[3 * p + q] = (p == q ? mu : 0.0);
            for (int i = 0; i < 3; ++i)
                a[3 * p + q] += channel(jacobian[p], i) * channel(jacobian[q], i);
        }
        for (int i = 0; i < 3; ++i) b[p] -= channel(jacobian[p], i) * channel(residual, i);
    }
    const auto d = solve_cholesky(std::move(a), std::move(b));
    if (!d) return {0, 0, 0};
    return {(*d)[0], (*d)[1], (*d)[2]};
}

double error_of(const Rgb& colour, const Rgb& target) {
    return std::max({std::abs(colour.r - target.r), std::abs(colour.g - target.g),
                     std::abs(colour.b - target.b)});
}

// Levenberg-Marquardt from `c` towards `target`; returns the error reached.
double solve(std::array<double, 3>& c, const Rgb& target, int iterations) {
    Rgb colour, jacobian[3];
    colour_and_jacobian(c, colour, jacobian);
    double error = error_of(colour, target), mu = 1e-6;
    for (int it = 0; it < iterations && error > 1e-13; ++it) {
        const std::array<double, 3> d = step(jacobian, colour + target * -1.0, mu);
        std::array<double, 3> trial = {c[0] + d[0], c[1] + d[1], c[2] + d[2]};
        Rgb trial_colour, trial_jacobian[3];
        colour_and_jacobian(trial, trial_colour, trial_jacobian);
        const double trial_error = error_of(trial_colour, target);
        if (trial_error < error) {
            c = trial;
            colour = trial_colour;
            for (int k = 0; k < 3; ++k) jacobian[k] = trial_jacobian[k];
            error = trial_error;
            mu = std::max(mu * 0.1, 1e-12);
        } else {
            mu *= 10;
            if (mu > 1e8) break;
        }
    }
    return error;
}

// The sigmoid's y for a constant value v in (0, 1): sigmoid(y) = v.
double inverse_sigmoid(double v) {
    const double t = 2 * v - 1;
    return t / std::sqrt(1 - t * t);
}

}  // namespace

double SigmoidPolynomial::eval(double nm) const {
    if (nm < kLambdaMinNm || nm > kLambdaMaxNm) return 0.0;
    return sigmoid(polynomial(c, (nm - kCentreNm) / kHalfWidthNm));
}

Rgb smooth_reflectance_colour(const SigmoidPolynomial& s) {
    Rgb colour, jacobian[3];
    colour_and_jacobian(s.c, colour, jacobian);
    return colour;
}

std::optional<SigmoidPolynomial> fit_smooth_reflectance(const Rgb& rgb, double tolerance) {
    const double lo = std::min({rgb.r, rgb.g, rgb.b}), hi = std::max({rgb.r, rgb.g, rgb.b});
    if (lo < 0 || hi > 1) return std::nullopt;
    // From the grey of the same mean, out to the colour in steps: each solve starts close.
    const double mean = std::clamp((rgb.r + rgb.g + rgb.b) / 3, 1e-3, 1 - 1e-3);
    SigmoidPolynomial s;
    s.c = {0, 0, inverse_sigmoid(mean)};
    if (hi - lo == 0 && hi > 0 && hi < 1) return s;  // a grey: the constant, exactly
    const Rgb grey{mean, mean, mean};
    constexpr int kSteps = 16;
    double error = 0;
    for (int k = 1; k <= kSteps; ++k) {
        const double t = static_cast<double>(k) / kSteps;
        error = solve(s.c, grey * (1 - t) + rgb * t, k == kSteps ? 200 : 30);
    }
    if (!(error <= tolerance * std::max(hi, 1e-12))) return std::nullopt;
    return s;
}

namespace {

class SmoothIlluminant final : public Spectrum {
public:
    SmoothIlluminant(SigmoidPolynomial shape, double scale)
        : m_shape(shape), m_scale(scale), m_d65(d65_spectrum()) {}
    double eval(double nm) const override { return m_scale * m_shape.eval(nm) * m_d65->eval(nm); }

private:
    SigmoidPolynomial m_shape;
    double m_scale;
    SpectrumPtr m_d65;
};

}  // namespace

SpectrumPtr smooth_illuminant_from_rgb(const Rgb& rgb) {
    const double hi = std::max({rgb.r, rgb.g, rgb.b}), lo = std::min({rgb.r, rgb.g, rgb.b});
    if (hi <= 0 || lo < 0 || hi == lo) return illuminant_from_rgb(rgb);
    // Fitted at a quarter of white at most: dim saturated colours are in reach of the
    // sigmoids (narrower humps), bright ones may not be.
    for (double brightness : {0.5, 0.25, 0.1}) {
        const double scale = hi / brightness;
        if (const auto s = fit_smooth_reflectance(rgb * (1.0 / scale)))
            return std::make_shared<SmoothIlluminant>(*s, scale);
    }
    return illuminant_from_rgb(rgb);
}

}  // namespace lenslab
