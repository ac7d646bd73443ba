// Issue 39: smooth spectra for RGB colours (optics/smooth_spectrum.h, Jakob and Hanika 2019).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "optics/smooth_spectrum.h"

namespace lenslab {
namespace {

double worst_error(const Rgb& got, const Rgb& want) {
    return std::max({std::abs(got.r - want.r), std::abs(got.g - want.g), std::abs(got.b - want.b)});
}

// Greys are the constant spectrum: their colour is exact (to rounding).
TEST(SmoothSpectrum, GreyStaysGrey) {
    for (double v : {0.02, 0.18, 0.5, 0.8, 0.98}) {
        const auto s = fit_smooth_reflectance({v, v, v});
        ASSERT_TRUE(s) << v;
        EXPECT_EQ(s->c[0], 0.0);
        EXPECT_EQ(s->c[1], 0.0);
        for (double nm : {400.0, 550.0, 700.0}) EXPECT_NEAR(s->eval(nm), v, 1e-12);
        const Rgb c = spectrum_to_rgb(*smooth_illuminant_from_rgb({v, v, v}));
        EXPECT_LT(worst_error(c, {v, v, v}), 1e-6 * v) << v;
    }
}

// Colours over a grid of the sRGB cube round-trip (colour -> spectrum -> colour, the colour
// being spectrum_to_rgb of D65 times it) within 1% of their brightest channel, and the
// spectra are reflectances (within [0, 1]).
TEST(SmoothSpectrum, ColoursRoundTripWithinOnePercent) {
    const double levels[] = {0.05, 0.25, 0.5, 0.75, 0.95};
    int fitted = 0, tried = 0;
    double worst = 0;
    for (double r : levels) {
        for (double g : levels) {
            for (double b : levels) {
                const Rgb want{r, g, b};
                ++tried;
                const auto s = fit_smooth_reflectance(want, 0.01);
                if (!s) {
                    std::printf("not reached: %.2f %.2f %.2f\n", r, g, b);
                    continue;
                }
                ++fitted;
                worst = std::max(
                    worst, worst_error(smooth_reflectance_colour(*s), want) / std::max({r, g, b}));
                for (double nm = 360; nm <= 830; nm += 10) {
                    EXPECT_GE(s->eval(nm), 0.0);
                    EXPECT_LE(s->eval(nm), 1.0);
                }
            }
        }
    }
    std::printf("%d of %d colours fitted, worst error %.2e of the brightest channel\n", fitted,
                tried, worst);
    EXPECT_LT(worst, 0.01);
    EXPECT_GT(fitted, tried * 9 / 10);
}

// Saturated lights, the sRGB primaries and secondaries at full brightness, become smooth
// illuminants of their colour within 1% (fitted dimmer, where the sigmoids reach them).
TEST(SmoothSpectrum, SaturatedLightsKeepTheirColour) {
    const Rgb lights[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1},     {1, 1, 0},
                          {0, 1, 1}, {1, 0, 1}, {1, 0.5, 0.2}, {3, 1, 0.5}};
    for (const Rgb& want : lights) {
        const SpectrumPtr s = smooth_illuminant_from_rgb(want);
        const Rgb got = spectrum_to_rgb(*s);
        const double scale = std::max({want.r, want.g, want.b});
        EXPECT_LT(worst_error(got, want) / scale, 0.01)
            << want.r << " " << want.g << " " << want.b << " -> " << got.r << " " << got.g << " "
            << got.b;
        // No edges: neighbouring nanometres differ little (boxes jump at 490 and 585 nm).
        double jump = 0;
        for (double nm = 400; nm < 700; nm += 1)
            jump = std::max(jump, std::abs(s->eval(nm + 1) - s->eval(nm)) /
                                      std::max(s->eval(nm), 1e-3 * scale));
        EXPECT_LT(jump, 0.2) << want.r << " " << want.g << " " << want.b;
    }
}

}  // namespace
}  // namespace lenslab
