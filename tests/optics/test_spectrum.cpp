// Colour science: CIE integrals, white, greys, and the colours of spectra.

#include <gtest/gtest.h>

#include <cmath>

#include "math/rng.h"
#include "optics/spectrum.h"

namespace lenslab {
namespace {

TEST(Spectrum, CieYIntegral) {
    // The 1931 y-bar integrates to 106.857 (CIE 015:2018; sum of the 1 nm table).
    EXPECT_NEAR(cie_y_integral(), 106.857, 0.05);
    EXPECT_NEAR(cie_xyz_bar(555).y, 1.0, 2e-3);  // peak of photopic sensitivity
}

TEST(Spectrum, D65IsWhiteAndGreysStayGrey) {
    const Rgb white = spectrum_to_rgb(*d65_spectrum());
    EXPECT_NEAR(white.r, 1.0, 1e-9);
    EXPECT_NEAR(white.g, 1.0, 1e-9);
    EXPECT_NEAR(white.b, 1.0, 1e-9);
    // A grey reflectance lit by D65, estimated by hero wavelengths, renders grey.
    const auto grey = reflectance_from_rgb({0.18, 0.18, 0.18});
    const auto light = d65_spectrum();
    Rng rng(3, 0);
    Rgb sum;
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
        const auto w = SampledWavelengths::sample((i + rng.uniform()) / n);
        sum += to_rgb(grey->sample(w) * light->sample(w), w);
    }
    EXPECT_NEAR(sum.r / n, 0.18, 1e-3);
    EXPECT_NEAR(sum.g / n, 0.18, 1e-3);
    EXPECT_NEAR(sum.b / n, 0.18, 1e-3);
}

TEST(Spectrum, RgbRoundTripsThroughTheBands) {
    for (const Rgb c : {Rgb{0.75, 0.12, 0.1}, Rgb{0.2, 0.5, 0.3}, Rgb{0.1, 0.2, 0.8}}) {
        const Rgb back = spectrum_to_rgb(*illuminant_from_rgb(c));
        EXPECT_NEAR(back.r, c.r, 1e-9);
        EXPECT_NEAR(back.g, c.g, 1e-9);
        EXPECT_NEAR(back.b, c.b, 1e-9);
    }
    // Reflectances never exceed 1.
    const auto r = reflectance_from_rgb({1, 0, 0});
    for (double nm = 360; nm <= 830; nm += 5) EXPECT_LE(r->eval(nm), 1.0);
}

// The band colours split spectrum_to_rgb's integral by band: they sum to it, whatever the
// spectrum (a band-edge crossing grid point, or a coarser sum, would break this).
TEST(Spectrum, BandColoursSumToTheSpectrumsColour) {
    for (const SpectrumPtr& s : {d65_spectrum(), blackbody_spectrum(2700), line_spectrum(532),
                                 line_spectrum(489.9), illuminant_from_rgb({0.75, 0.12, 0.1})}) {
        const Rgb whole = spectrum_to_rgb(*s);
        const Rgb sum = s->band_colour().total();
        const double scale = whole.max_component();
        EXPECT_NEAR(sum.r, whole.r, 1e-12 * scale);
        EXPECT_NEAR(sum.g, whole.g, 1e-12 * scale);
        EXPECT_NEAR(sum.b, whole.b, 1e-12 * scale);
    }
    // A laser line lies in one band: the others are black.
    const BandColour green = line_spectrum(532)->band_colour();
    EXPECT_EQ(green.band[0].max_component(), 0.0);
    EXPECT_EQ(green.band[2].max_component(), 0.0);
}

TEST(Spectrum, GreyAlbedoUnderD65IsExactlyGrey) {
    // The colour of albedo x light is sum_b a_b band_b(light), with no wavelength sampling.
    for (double a : {0.18, 0.5, 0.8}) {
        const Rgb c = d65_spectrum()->band_colour().through(reflectance_bands(Rgb::grey(a)));
        EXPECT_NEAR(c.r, a, 1e-12);
        EXPECT_NEAR(c.g, a, 1e-12);
        EXPECT_NEAR(c.b, a, 1e-12);
    }
    // An RGB illuminant's band colours, computed from the bands directly, are its spectrum's.
    const Rgb rgb{0.3, 0.9, 0.4};
    const BandColour direct = illuminant_band_colour(rgb);
    const BandColour integrated = illuminant_from_rgb(rgb)->band_colour();
    for (int b = 0; b < 3; ++b) {
        EXPECT_NEAR(direct.band[b].r, integrated.band[b].r, 1e-12);
        EXPECT_NEAR(direct.band[b].g, integrated.band[b].g, 1e-12);
        EXPECT_NEAR(direct.band[b].b, integrated.band[b].b, 1e-12);
    }
    // And a coloured albedo under white light keeps its colour.
    const Rgb red =
        illuminant_band_colour({1, 1, 1}).through(reflectance_bands({0.75, 0.15, 0.12}));
    EXPECT_NEAR(red.r, 0.75, 1e-9);
    EXPECT_NEAR(red.g, 0.15, 1e-9);
    EXPECT_NEAR(red.b, 0.12, 1e-9);
}

TEST(Spectrum, ColoursOfLightSources) {
    // A 6504 K blackbody is close to D65 (D65's correlated colour temperature): near-neutral.
    const Rgb bb = spectrum_to_rgb(*blackbody_spectrum(6504));
    EXPECT_NEAR(bb.r / bb.g, 1.0, 0.08);
    EXPECT_NEAR(bb.b / bb.g, 1.0, 0.08);
    // Incandescent 2700 K is orange-red; a 650 nm line is red, 532 nm green, 450 nm blue.
    const Rgb warm = spectrum_to_rgb(*blackbody_spectrum(2700));
    EXPECT_GT(warm.r, warm.g);
    EXPECT_GT(warm.g, warm.b);
    const Rgb red = spectrum_to_rgb(*line_spectrum(650));
    EXPECT_GT(red.r, 10 * std::abs(red.g));
    const Rgb green = spectrum_to_rgb(*line_spectrum(532));
    EXPECT_GT(green.g, green.r);
    EXPECT_GT(green.g, green.b);
    const Rgb blue = spectrum_to_rgb(*line_spectrum(450));
    EXPECT_GT(blue.b, blue.g);
    // Every light spectrum carries the radiant power of D65 white.
    auto power = [](const Spectrum& s) {
        double p = 0;
        for (double nm = 360.05; nm < 830; nm += 0.1) p += s.eval(nm) * 0.1;
        return p;
    };
    EXPECT_NEAR(power(*blackbody_spectrum(3000)) / power(*d65_spectrum()), 1.0, 1e-3);
    EXPECT_NEAR(power(*line_spectrum(532)) / power(*d65_spectrum()), 1.0, 1e-3);
}

TEST(Spectrum, WavelengthSamplingFollowsALaserLine) {
    const auto line = line_spectrum(532, 1.0);
    Rng rng(5, 0);
    for (int i = 0; i < 1000; ++i) {
        double nm;
        const double pdf = line->sample_wavelength(rng.uniform(), nm);
        EXPECT_NEAR(nm, 532, 5.0);
        EXPECT_GT(pdf, 0.0);
    }
}

}  // namespace
}  // namespace lenslab
