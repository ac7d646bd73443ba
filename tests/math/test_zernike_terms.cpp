// Zernike terms as polynomials in x and y (for a Zernike sag) against their values from the
// radial polynomial and the angle (the definition, zernike_terms.h).

#include <gtest/gtest.h>

#include <cmath>

#include "math/rng.h"
#include "math/zernike_terms.h"

namespace lenslab {
namespace {

double monomials_at(const std::vector<double>& c, int n, double x, double y) {
    double sum = 0;
    for (int a = 0; a <= n; ++a) {
        for (int b = 0; b <= n; ++b) sum += c[a * (n + 1) + b] * std::pow(x, a) * std::pow(y, b);
    }
    return sum;
}

TEST(ZernikeTerms, EachTermAsAPolynomialInXAndYIsItsValue) {
    Rng rng(5, 9);
    for (ZernikeOrdering ordering : {ZernikeOrdering::Noll, ZernikeOrdering::Fringe}) {
        const int terms = ordering == ZernikeOrdering::Noll ? 66 : 37;
        for (int j = 1; j <= terms; ++j) {
            const int n = zernike_index(ordering, j).n;
            const std::vector<double> c = zernike_monomials(ordering, j);
            ASSERT_EQ(c.size(), size_t((n + 1) * (n + 1)));
            for (int i = 0; i < 20; ++i) {
                const double rho = std::sqrt(rng.uniform()), theta = 2 * M_PI * rng.uniform();
                const double x = rho * std::cos(theta), y = rho * std::sin(theta);
                EXPECT_NEAR(monomials_at(c, n, x, y), zernike_value(ordering, j, rho, theta), 1e-10)
                    << zernike_ordering_name(ordering) << " Z" << j;
            }
        }
    }
    // Noll Z4 = √3 (2ρ² − 1): √3 · (−1 + 2x² + 2y²).
    const std::vector<double> z4 = zernike_monomials(ZernikeOrdering::Noll, 4);
    EXPECT_NEAR(z4[0], -std::sqrt(3.0), 1e-14);
    EXPECT_NEAR(z4[2 * 3 + 0], 2 * std::sqrt(3.0), 1e-14);
    EXPECT_NEAR(z4[0 * 3 + 2], 2 * std::sqrt(3.0), 1e-14);
}

}  // namespace
}  // namespace lenslab
