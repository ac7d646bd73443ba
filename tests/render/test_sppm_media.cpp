// sppm in fog: light that reaches the fog only by way of a mirror comes from volume photons
// (the beam radiance estimate), light straight from a beam from the exact single-scattering
// sum. Both must give the same in-scattered light: a beam seen side-on before and after a
// perfect mirror differs only by the fog's transmittance along the way.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/render_session.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

double luminance_at(const Film& f, int x, int y) {
    const PixelRgb& p = f.at(x, y);
    return 0.2126 * p.r + 0.7152 * p.g + 0.0722 * p.b;
}

TEST(SppmMedia, PhotonsShowAMirroredBeamAsBrightAsTheExactSumShowsTheBeam) {
    // A beam along +x at z = -1 meets a perfect mirror at x = 1 turned 45 degrees, and goes on
    // along +z, all in isotropic fog (no angle matters) seen from straight above. Summed across
    // the beam, the image's in-scattered light at the same distance from the camera differs
    // only by exp(-sigma_t s), s the way the light travelled from one window to the other.
    const double sigma_t = 0.05;
    const Scene scene = parse_scene(R"({
      "camera": {"position": [0, 8, 0], "look_at": [0, 0, 0], "up": [0, 0, -1], "fov": 40},
      "render": {"width": 96, "height": 96, "integrator": "sppm", "passes": 24,
                 "pass_photons": 80000, "max_depth": 4},
      "atmosphere": {"scattering": 0.05},
      "objects": [{"type": "rectangle", "center": [1, 0, -1], "normal": [-0.70710678, 0, 0.70710678],
                   "size": [0.6, 0.6], "material": {"color": 0, "specular": 1}}],
      "lights": [{"type": "beam", "origin": [-4, 0, -1], "direction": [1, 0, 0], "radius": 0.05,
                  "power": 20}]
    })");
    RenderControl control;
    const Film f = render_scene(scene, control).film;
    const int w = f.width(), h = f.height();
    // The beams are the brightest row and column.
    auto row_sum = [&](int y) {
        double s = 0;
        for (int x = 0; x < w; ++x) s += luminance_at(f, x, y);
        return s;
    };
    auto column_sum = [&](int x) {
        double s = 0;
        for (int y = 0; y < h; ++y) s += luminance_at(f, x, y);
        return s;
    };
    int beam_row = 0, mirrored_column = 0;
    for (int y = 1; y < h; ++y)
        if (row_sum(y) > row_sum(beam_row)) beam_row = y;
    for (int x = 1; x < w; ++x)
        if (column_sum(x) > column_sum(mirrored_column)) mirrored_column = x;
    // Windows 24 to 40 pixels from the mirror along each beam, summed 8 pixels either side.
    const double px_per_unit = (h / 2.0) / (8.0 * std::tan(20.0 * 3.14159265358979 / 180.0));
    const int toward_beam = mirrored_column > w / 2 ? -1 : 1;
    const int side = column_sum(mirrored_column) > 0 &&
                             luminance_at(f, mirrored_column, std::max(0, beam_row - 30)) >
                                 luminance_at(f, mirrored_column, std::min(h - 1, beam_row + 30))
                         ? -1
                         : 1;
    double direct = 0, mirrored = 0;
    for (int k = 24; k < 40; ++k) {
        for (int j = -8; j <= 8; ++j) {
            direct += luminance_at(f, mirrored_column + toward_beam * k, beam_row + j);
            mirrored += luminance_at(f, mirrored_column + j, beam_row + side * k);
        }
    }
    // From the middle of one window to the middle of the other, by way of the mirror.
    const double s = 2 * 32 / px_per_unit;
    const double expected = std::exp(-sigma_t * s);
    std::printf("beam row %d, mirrored column %d; mirrored / direct = %.4f, expected %.4f\n",
                beam_row, mirrored_column, mirrored / direct, expected);
    EXPECT_GT(direct, 0.0);
    EXPECT_NEAR(mirrored / direct, expected, 0.06 * expected);
}

TEST(SppmMedia, TheSameImageAtAnyThreadCount) {
    // Volume photons are gathered per pixel from one hierarchy over the pass's photons, in
    // photon order: the image must not depend on the threads.
    const Scene scene = parse_scene(R"({
      "camera": {"position": [0, 0, 6], "look_at": [0, 0, 0]},
      "render": {"width": 40, "height": 24, "integrator": "sppm", "passes": 3},
      "objects": [{"type": "box", "center": [0, 0, 0], "size": [4, 2, 2],
                   "medium": {"scattering": 0.3, "g": 0.4}},
                  {"type": "sphere", "center": [0, 0, 0], "radius": 0.5,
                   "material": {"transparency": 1, "ior": 1.5}}],
      "lights": [{"type": "beam", "origin": [-3, 0.2, 0], "direction": [1, 0, 0], "radius": 0.2,
                  "power": 5}]
    })");
    RenderControl one, two;
    const Film a = render_scene(scene, one, 1).film;
    const Film b = render_scene(scene, two, 2).film;
    double total = 0;
    for (size_t i = 0; i < a.pixels().size(); ++i) {
        EXPECT_EQ(a.pixels()[i].g, b.pixels()[i].g) << "pixel " << i;
        total += a.pixels()[i].g;
    }
    EXPECT_GT(total, 0.0);
}

}  // namespace
}  // namespace lenslab
