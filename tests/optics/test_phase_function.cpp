// The Henyey–Greenstein phase function against its defining properties (Henyey and
// Greenstein 1941): it integrates to 1 over the sphere, its mean cosine is g, it is 1/(4 pi)
// for g = 0, and the sampler draws directions with exactly its density.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "math/rng.h"
#include "optics/phase_function.h"

namespace lenslab {
namespace {

// 2 pi times the integral of f(cos) p(cos) over cos in [a, b] (Simpson, n even).
template <class F>
double phase_integral(const HenyeyGreenstein& p, double a, double b, F f, int n = 20000) {
    const double h = (b - a) / n;
    double sum = 0;
    for (int i = 0; i <= n; ++i) {
        const double c = a + i * h;
        const double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
        sum += w * f(c) * p.eval(c);
    }
    return 2 * kPi * sum * h / 3;
}

TEST(HenyeyGreenstein, IntegratesToOneWithMeanCosineG) {
    for (double g : {-0.7, 0.0, 0.3, 0.9}) {
        SCOPED_TRACE(g);
        const HenyeyGreenstein p(g);
        EXPECT_NEAR(phase_integral(p, -1, 1, [](double) { return 1.0; }), 1.0, 1e-6);
        EXPECT_NEAR(phase_integral(p, -1, 1, [](double c) { return c; }), g, 1e-6);
    }
    EXPECT_DOUBLE_EQ(HenyeyGreenstein(0).eval(0.4), 1 / (4 * kPi));
}

// Samples binned by cos theta land in each bin as often as the density says (within five
// standard deviations of the binomial count), and keep the azimuth uniform.
TEST(HenyeyGreenstein, SamplesFollowTheDensity) {
    const Vec3 forward = normalize(Vec3{1, 2, -0.5});
    Rng rng(7, 3);
    for (double g : {-0.5, 0.0, 0.8}) {
        SCOPED_TRACE(g);
        const HenyeyGreenstein p(g);
        constexpr int kBins = 20, kSamples = 200000;
        std::vector<int> counts(kBins, 0);
        double mean_sideways = 0;
        const Frame f = Frame::from_axis(forward);
        for (int i = 0; i < kSamples; ++i) {
            const Vec3 d = p.sample(forward, rng.uniform(), rng.uniform());
            ASSERT_NEAR(length(d), 1, 1e-9);
            const double c = dot(d, forward);
            counts[std::min(kBins - 1, int((c + 1) / 2 * kBins))]++;
            mean_sideways += dot(d, f.u);
        }
        for (int b = 0; b < kBins; ++b) {
            const double lo = -1 + 2.0 * b / kBins, hi = lo + 2.0 / kBins;
            const double prob = phase_integral(
                p, lo, hi, [](double) { return 1.0; }, 2000);
            const double sigma = std::sqrt(kSamples * prob * (1 - prob));
            EXPECT_NEAR(counts[b], kSamples * prob, 5 * sigma + 1) << "bin " << b;
        }
        EXPECT_NEAR(mean_sideways / kSamples, 0, 0.01);
    }
}

}  // namespace
}  // namespace lenslab
