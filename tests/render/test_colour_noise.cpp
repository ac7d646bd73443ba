// Issue 13: no colour noise at 1 sample per pixel. A path that meets no dispersive surface
// carries the whole spectrum, so a white light on a grey floor is grey in every pixel; a path
// through dispersive glass still splits the colours (render/path_colour.h).

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "render/render_session.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

// A grey floor (albedo 0.5) seen obliquely, filling the 64 x 48 image, at 1 sample per pixel.
std::string grey_floor_scene(const std::string& integrator, const std::string& objects,
                             const std::string& lights) {
    return R"({
      "camera": {"position": [0, 2, -3], "look_at": [0, 0, 0.5], "fov": 50},
      "render": {"width": 64, "height": 48, "spp": 1, "photons": 20000, "passes": 1, "integrator": ")" +
           integrator + R"("},
      "objects": [
        {"type": "triangle", "vertices": [[-50, 0, -50], [-50, 0, 50], [50, 0, 50]], "material": {"color": 0.5}},
        {"type": "triangle", "vertices": [[-50, 0, -50], [50, 0, 50], [50, 0, -50]], "material": {"color": 0.5}})" +
           objects + R"(],
      "lights": [)" +
           lights + "]}";
}

Film render_json(const std::string& json) {
    RenderControl control;
    return render_scene(parse_scene(json), control).film;
}

double chroma(const PixelRgb& p) { return std::max({p.r, p.g, p.b}) / std::min({p.r, p.g, p.b}); }

// Every pixel, and the image's mean, neutral: largest channel over smallest below 1.01.
void expect_grey_in_every_pixel(const Film& film) {
    double worst = 1.0, sum[3] = {0, 0, 0};
    for (const PixelRgb& p : film.pixels()) {
        ASSERT_GT(std::min({p.r, p.g, p.b}), 0.0f) << "every pixel sees the lit floor";
        worst = std::max(worst, chroma(p));
        sum[0] += p.r;
        sum[1] += p.g;
        sum[2] += p.b;
    }
    const double mean = std::max({sum[0], sum[1], sum[2]}) / std::min({sum[0], sum[1], sum[2]});
    std::printf("largest channel / smallest, minus 1: worst pixel %.2e, image mean %.2e\n",
                worst - 1, mean - 1);
    EXPECT_LT(worst, 1.01);
    EXPECT_LT(mean, 1.01);
}

class ColourNoise : public ::testing::TestWithParam<const char*> {};

TEST_P(ColourNoise, WhitePointLightOnGreyFloorIsGreyInEveryPixel) {
    expect_grey_in_every_pixel(render_json(grey_floor_scene(
        GetParam(), "", R"({"type": "point", "position": [0, 2, 0.5], "power": 100})")));
    // Any light spectrum gives the floor that light's colour, evenly: here a D65 spectrum.
    expect_grey_in_every_pixel(render_json(grey_floor_scene(
        GetParam(), "",
        R"({"type": "point", "position": [0, 2, 0.5], "power": 100, "spectrum": "d65"})")));
}

TEST_P(ColourNoise, EmittingSphereOnGreyFloorIsGreyInEveryPixel) {
    expect_grey_in_every_pixel(render_json(grey_floor_scene(
        GetParam(),
        R"(, {"type": "sphere", "center": [0, 1.5, 1], "radius": 0.2, "material": {"color": 0, "emission": {"intensity": 20}}})",
        "")));
}

INSTANTIATE_TEST_SUITE_P(Integrators, ColourNoise,
                         ::testing::Values("whitted", "photon_map", "path", "sppm"));

// The floor through a glass ball: with a constant index it stays grey, with a dispersive
// glass (N-SF11) each camera sample keeps one wavelength there (dispersion_samples 1: no
// split, test_dispersion_split.cpp has the split) and the pixels are coloured.
TEST(ColourNoiseThroughGlass, DispersiveGlassStillSplitsTheColours) {
    auto ball = [](const std::string& glass) {
        return grey_floor_scene(
            "whitted",
            R"(, {"type": "sphere", "center": [0, 0.6, -0.5], "radius": 0.5, "material": {"color": 1, "transparency": 1, )" +
                glass + "}}",
            R"({"type": "point", "position": [0, 2, 0.5], "power": 100})");
    };
    auto unsplit = [](const std::string& json) {
        Scene scene = parse_scene(json);
        scene.render.dispersion_samples = 1;
        RenderControl control;
        return render_scene(scene, control).film;
    };
    const Film plain = unsplit(ball(R"("ior": 1.5)"));
    const Film dispersive = unsplit(ball(R"("glass": "N-SF11")"));
    // Pixels that see the ball: they differ between the two renders.
    int through = 0, coloured = 0;
    double worst_plain = 1.0;
    for (size_t i = 0; i < plain.pixels().size(); ++i) {
        const PixelRgb& a = plain.pixels()[i];
        const PixelRgb& b = dispersive.pixels()[i];
        if (a.r == b.r && a.g == b.g && a.b == b.b) continue;
        ++through;
        if (std::min({a.r, a.g, a.b}) > 0) worst_plain = std::max(worst_plain, chroma(a));
        coloured += std::min({b.r, b.g, b.b}) <= 0 || chroma(b) > 1.2;
    }
    EXPECT_GT(through, 100);
    EXPECT_LT(worst_plain, 1.01);
    EXPECT_GT(coloured, through * 9 / 10);
}

}  // namespace
}  // namespace lenslab
