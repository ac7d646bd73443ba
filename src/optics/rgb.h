#pragma once
// Linear RGB triple for radiometric quantities (radiance, power, albedo).
// The spectral issue replaces transport in RGB by sampled wavelengths; this type then
// remains for colours the user types and for the film.

#include <algorithm>
#include <cmath>

namespace lenslab {

struct Rgb {
    double r = 0, g = 0, b = 0;

    constexpr Rgb() = default;
    constexpr Rgb(double r_, double g_, double b_) : r(r_), g(g_), b(b_) {}
    static constexpr Rgb grey(double v) { return {v, v, v}; }

    constexpr Rgb& operator+=(const Rgb& o) {
        r += o.r;
        g += o.g;
        b += o.b;
        return *this;
    }
    constexpr Rgb& operator*=(const Rgb& o) {
        r *= o.r;
        g *= o.g;
        b *= o.b;
        return *this;
    }
    constexpr Rgb& operator*=(double s) {
        r *= s;
        g *= s;
        b *= s;
        return *this;
    }

    constexpr double max_component() const { return std::max(r, std::max(g, b)); }
    constexpr double average() const { return (r + g + b) / 3.0; }
    constexpr bool is_black() const { return r == 0 && g == 0 && b == 0; }
    bool is_finite() const { return std::isfinite(r) && std::isfinite(g) && std::isfinite(b); }
};

constexpr Rgb operator+(Rgb a, const Rgb& b) { return a += b; }
constexpr Rgb operator*(Rgb a, const Rgb& b) { return a *= b; }
constexpr Rgb operator*(Rgb a, double s) { return a *= s; }
constexpr Rgb operator*(double s, Rgb a) { return a *= s; }

}  // namespace lenslab
