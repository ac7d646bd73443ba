#include "analysis/diffraction/zernike.h"

#include <cmath>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>

#include "math/cholesky.h"

namespace lenslab {

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
