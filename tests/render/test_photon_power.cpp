// A photon's power through dispersion: where a dispersive refraction makes a photon pick one
// wavelength of its light's spectrum, its radiant power must stay what the light gave it:
// its colour is then that of one wavelength of the line carrying exactly that power.
// Two bugs this found: with the wavelength drawn from a 1 nm histogram but the power taken
// from the spectrum's value at that wavelength, a photon of a laser line could come out up to
// 15 times brighter than its light (or black); and a 0.05 nm line's power was normalised on
// a 0.25 nm grid, making the light itself 5.7 times too bright.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "render/integrators/photon_map.h"
#include "render/photon_tracer.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

// A thin laser beam (line `nm`, `width` nm) through a glass block of N-SF11 (dispersive) onto
// a white screen: every photon that arrives was refracted twice, so it picked a wavelength.
// The index is N-SF11's Sellmeier model given as `ior`, not the catalogue glass: that one
// absorbs (0.4% over the sphere at 550 nm), and here only the dispersion's bookkeeping is
// under test (tests/analysis/test_glass_absorption.cpp checks the absorption).
Scene laser_through_glass(double nm, double width) {
    return parse_scene(R"({
      "camera": {"position": [0, 0, -10], "look_at": [0, 0, 0]},
      "render": {"photons": 20000, "max_depth": 8},
      "objects": [
        {"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": {"transparency": 1, "ior": {"model": "sellmeier", "B": [1.73759695, 0.313747346, 1.89878101], "C": [0.013188707, 0.0623068142, 155.23629]}}},
        {"type": "triangle", "vertices": [[-20, -20, 5], [20, 20, 5], [20, -20, 5]], "material": {"color": 1}},
        {"type": "triangle", "vertices": [[-20, -20, 5], [-20, 20, 5], [20, 20, 5]], "material": {"color": 1}}
      ],
      "lights": [{"type": "beam", "origin": [0, 0, -3], "direction": [0, 0, 1], "radius": 0.3, "power": 1,
                  "spectrum": {"line": )" +
                       std::to_string(nm) + R"(, "width": )" + std::to_string(width) + "}}]}");
}

// How far `got` is from the colour of a single wavelength near `nm` (within 6 `width` + 1 nm)
// carrying `power`, relative to that colour: 0 when some wavelength matches.
double distance_from_one_wavelength(const Rgb& got, double power, double nm, double width) {
    double best = INFINITY;
    // The wavelength is drawn from a 1 nm histogram: it may lie up to 1 nm beyond the line.
    for (double l = nm - 6 * width - 1; l <= nm + 6 * width + 1; l += 0.002) {
        const Rgb c = sample_to_rgb(power, l, 1.0);
        const double scale = std::max({std::abs(c.r), std::abs(c.g), std::abs(c.b)});
        best = std::min(
            best, std::max({std::abs(got.r - c.r), std::abs(got.g - c.g), std::abs(got.b - c.b)}) /
                      scale);
    }
    return best;
}

void expect_caustic_photons_keep_the_beams_power(double nm, double width) {
    SCOPED_TRACE("line " + std::to_string(nm) + " nm, width " + std::to_string(width) + " nm");
    const Scene scene = laser_through_glass(nm, width);
    // Emitted photons only: they keep their power through the glass (roulette); aimed ones
    // split there (RandomScenes.NoPhotonGainsPower checks them).
    PhotonTracingSettings settings = photon_tracing_settings(scene);
    settings.aim = false;
    settings.photons_per_light = scene.render.photons;
    // The radiant power one photon leaves with: the beam's over the photon count. A light's
    // `power` 1 is the radiant power of D65 white (docs/scene-format.md), whatever the line.
    const double beam = radiant_power(*scene.beams[0].spectrum);
    EXPECT_NEAR(beam / radiant_power(*d65_spectrum()), 1.0, 1e-6);
    const double emitted = beam / settings.photons_per_light;
    RenderControl control;
    const PhotonMap map = trace_photons(scene, settings, control);
    ASSERT_GT(map.caustic().size(), 1000u);
    double worst = 0;
    for (size_t i = 0; i < 500; ++i) {
        // Stored on white (p_diffuse = 1) after two refractions and perhaps reflections
        // inside, each kept by Russian roulette with the power unchanged.
        const Rgb got = map.caustic().begin()[i].flux();
        worst =
            std::max(worst, distance_from_one_wavelength(got, emitted, nm, std::max(width, 0.1)));
    }
    EXPECT_LT(worst, 2e-3);
}

TEST(PhotonPower, DispersedLaserPhotonsKeepTheirPower) {
    expect_caustic_photons_keep_the_beams_power(550, 0.05);  // narrower than a 1 nm bin
    expect_caustic_photons_keep_the_beams_power(532.3, 0.3);
    expect_caustic_photons_keep_the_beams_power(632.8, 1);
}

}  // namespace
}  // namespace lenslab
