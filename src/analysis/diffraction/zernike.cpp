#include "analysis/diffraction/zernike.h"

#include <cmath>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>

#include "math/cholesky.h"

namespace lenslab {

namespace {

constexpr int kFringeTerms = 37;

double factorial(int k) {
    double f = 1;
    for (int i = 2; i <= k; ++i) f *= i;
    return f;
}

// R_n^m(ρ), m ≥ 0 and n − m even.
double zernike_radial(int n, int m, double rho) {
    double sum = 0;
    for (int s = 0; s <= (n - m) / 2; ++s) {
        const double c = factorial(n - s) /
                         (factorial(s) * factorial((n + m) / 2 - s) * factorial((n - m) / 2 - s));
        sum += (s % 2 ? -c : c) * std::pow(rho, n - 2 * s);
    }
    return sum;
}

ZernikeIndex noll_index(int j) {
    int n = 0;
    while ((n + 1) * (n + 2) / 2 < j) ++n;
    const int k = j - n * (n + 1) / 2 - 1;  // place within the row of order n
    const int m = n % 2 == 0 ? 2 * ((k + 1) / 2) : 2 * (k / 2) + 1;
    return {n, m == 0 || j % 2 == 0 ? m : -m};
}

ZernikeIndex fringe_index(int j) {
    if (j == kFringeTerms) return {12, 0};  // the set ends with 5th-order spherical's successor
    // Groups of equal (n + |m|)/2 = g hold |m| = g, g−1, ..., 0, cos before sin.
    int first = 1;  // the first term of group g
    for (int g = 0;; ++g) {
        const int size = 2 * g + 1;
        if (j < first + size) {
            const int k = j - first;
            const int m = g - k / 2;
            return {2 * g - m, k % 2 == 0 ? m : -m};
        }
        first += size;
    }
}

}  // namespace

const char* zernike_ordering_name(ZernikeOrdering ordering) {
    return ordering == ZernikeOrdering::Noll ? "noll" : "fringe";
}

ZernikeIndex zernike_index(ZernikeOrdering ordering, int j) {
    if (j < 1) throw std::invalid_argument("Zernike terms count from 1");
    if (ordering == ZernikeOrdering::Fringe) {
        if (j > kFringeTerms)
            throw std::invalid_argument("the Fringe ordering has 37 terms; Noll has any number");
        return fringe_index(j);
    }
    return noll_index(j);
}

double zernike_value(ZernikeOrdering ordering, int j, double rho, double theta) {
    const ZernikeIndex z = zernike_index(ordering, j);
    const int m = std::abs(z.m);
    double value = zernike_radial(z.n, m, rho);
    if (z.m > 0) value *= std::cos(m * theta);
    if (z.m < 0) value *= std::sin(m * theta);
    if (ordering == ZernikeOrdering::Noll) value *= std::sqrt((m == 0 ? 1.0 : 2.0) * (z.n + 1));
    return value;
}

ZernikeFit fit_zernike(const PupilFunction& pupil, ZernikeOrdering ordering, int terms) {
    if (terms < 1) throw std::invalid_argument("a Zernike fit needs at least one term");
    zernike_index(ordering, terms);  // refuses a term the ordering lacks
    const size_t t = static_cast<size_t>(terms);
    // Normal equations Σ z zᵀ c = Σ z w over the passing samples.
    std::vector<double> gram(t * t, 0.0), rhs(t, 0.0), z(t);
    size_t count = 0;
    const auto each_sample = [&](auto&& visit) {
        for (int i = 0; i < pupil.size; ++i)
            for (int jj = 0; jj < pupil.size; ++jj) {
                const size_t cell = pupil.index(i, jj);
                if (!(pupil.amplitude[cell] > 0)) continue;
                const double x = pupil.coordinate(jj), y = pupil.coordinate(i);
                const double rho = std::hypot(x, y), theta = std::atan2(y, x);
                for (size_t k = 0; k < t; ++k)
                    z[k] = zernike_value(ordering, static_cast<int>(k) + 1, rho, theta);
                visit(pupil.opd_waves[cell]);
            }
    };
    each_sample([&](double w) {
        ++count;
        for (size_t a = 0; a < t; ++a) {
            rhs[a] += z[a] * w;
            for (size_t b = 0; b <= a; ++b) gram[a * t + b] += z[a] * z[b];
        }
    });
    if (count < t)
        throw std::invalid_argument("a Zernike fit of " + std::to_string(terms) + " terms needs " +
                                    "at least as many pupil samples; " + std::to_string(count) +
                                    " passed");
    for (size_t a = 0; a < t; ++a)
        for (size_t b = a + 1; b < t; ++b) gram[a * t + b] = gram[b * t + a];
    const std::optional<std::vector<double>> c = solve_cholesky(gram, rhs);
    if (!c)
        throw std::invalid_argument(
            "the pupil samples cannot tell the Zernike terms apart: "
            "sample the pupil more finely or fit fewer terms");
    ZernikeFit fit;
    fit.ordering = ordering;
    fit.coefficients = *c;
    double residual = 0;
    each_sample([&](double w) {
        for (size_t k = 0; k < t; ++k) w -= fit.coefficients[k] * z[k];
        residual += w * w;
    });
    fit.residual_rms = std::sqrt(residual / static_cast<double>(count));
    return fit;
}

}  // namespace lenslab
