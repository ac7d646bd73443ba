// The section view's colours: each light's rays traced at the wavelengths it emits (a
// laser's line; white light's F, d and C lines where glass disperses, else one path in the
// light's colour) and drawn in their true colours (issue 41).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "analysis/section/section_view.h"
#include "optics/spectrum.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

// A laser's rays are traced at its line and drawn in its colour, whatever the view's spread
// for white light: the smoke tank's 532 nm beams are green (issue 41).
TEST(SectionView, ALaserIsTracedAtItsLineInItsColour) {
    const Scene scene = load_scene_file(LENSLAB_SOURCE_DIR "/scenes/smoke_tank.json");
    const SectionPlane plane{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const SectionView view = make_section_view(scene, plane);
    ASSERT_GE(view.rays.size(), 10u);
    for (const SectionRayPath& r : view.rays) {
        EXPECT_NEAR(r.wavelength_nm, 532, 0.05);
        EXPECT_FALSE(r.whole_spectrum);
        EXPECT_GT(r.colour.g, 2 * std::max(r.colour.r, r.colour.b));
    }
    const RayDiagram d = section_diagram(scene, view);
    ASSERT_EQ(d.legend.size(), 1u);
    EXPECT_EQ(d.legend[0].text, "532.0 nm");
    EXPECT_GT(d.legend[0].colour.g, 2 * std::max(d.legend[0].colour.r, d.legend[0].colour.b));
}

// Single wavelengths take their hue: violet-blue, green, red.
TEST(SectionView, WavelengthColoursFollowTheSpectrum) {
    const Rgb blue = wavelength_rgb(450), green = wavelength_rgb(530), red = wavelength_rgb(650);
    EXPECT_EQ(std::max({blue.r, blue.g, blue.b}), blue.b);
    EXPECT_EQ(std::max({green.r, green.g, green.b}), green.g);
    EXPECT_EQ(std::max({red.r, red.g, red.b}), red.r);
    EXPECT_LT(red.b, 0.05);
}

// A broad light in dispersing glass is drawn in the F, d and C lines, each with the
// spectrum's share there: a 2000 K blackbody's C line outweighs its F line by Planck's law
// (B(656.3 nm) / B(486.1 nm) at 2000 K, computed here from the law itself).
TEST(SectionView, ABroadLightIsDrawnInItsLinesWeightedByItsSpectrum) {
    const std::vector<double> spread{kLineF, kLineD, kLineC};
    const auto planck = [](double nm, double kelvin) {
        const double h = 6.62607015e-34, c = 299792458, k = 1.380649e-23, l = nm * 1e-9;
        return 1 / (std::pow(l, 5) * (std::exp(h * c / (l * k * kelvin)) - 1));
    };
    const auto lines = section_wavelengths(*blackbody_spectrum(2000), spread, true);
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_DOUBLE_EQ(lines[2].weight, 1.0);  // the strongest
    EXPECT_NEAR(lines[0].weight, planck(kLineF, 2000) / planck(kLineC, 2000), 0.01);
    EXPECT_NEAR(lines[1].weight, planck(kLineD, 2000) / planck(kLineC, 2000), 0.01);
    // Without dispersion, one path in the light's own colour: a warm white.
    const auto one = section_wavelengths(*blackbody_spectrum(2000), spread, false);
    ASSERT_EQ(one.size(), 1u);
    EXPECT_TRUE(one[0].whole_spectrum);
    EXPECT_EQ(one[0].colour.r, 1.0);
    EXPECT_LT(one[0].colour.b, 0.5 * one[0].colour.r);
    // A laser line stays its line either way.
    const auto laser = section_wavelengths(*line_spectrum(632.8), spread, true);
    ASSERT_EQ(laser.size(), 1u);
    EXPECT_NEAR(laser[0].nm, 632.8, 0.05);
}

}  // namespace
}  // namespace lenslab
