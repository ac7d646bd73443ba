// Discs and rectangles render where they are: facing a pinhole camera, a disc of radius r
// at distance d covers pi (r / (d tan(fov / 2)))^2 / 4 of a square image whose vertical
// field of view is fov, and a rectangle its width x height share; lit from behind they
// show their lit side (both faces are surfaces).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "render/render_session.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

double lit_fraction(const std::string& object) {
    const Scene scene =
        parse_scene(R"({"camera": {"position": [0, 0, 10], "look_at": [0, 0, 0], "fov": 20},
        "render": {"width": 200, "height": 200, "spp": 4, "ambient": 1},
        "objects": [)" +
                    object + "]}");
    RenderControl control;
    const RenderResult r = render_scene(scene, control);
    int lit = 0;
    for (const PixelRgb& p : r.film.pixels()) lit += p.g > 0.4;
    return static_cast<double>(lit) / static_cast<double>(r.film.pixels().size());
}

TEST(FlatShapes, DiscCoversItsProjectedArea) {
    const double half = 10 * std::tan(10 * std::numbers::pi / 180);  // half the view at d = 10
    const double expected = std::numbers::pi / (4 * half * half);
    const double got =
        lit_fraction(R"({"type": "disc", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1,
        "material": {"color": 0.8}})");
    EXPECT_NEAR(got, expected, 0.02 * expected);
    // Its back face renders too (a disc is two-sided).
    EXPECT_NEAR(
        lit_fraction(R"({"type": "disc", "center": [0, 0, 0], "normal": [0, 0, -1], "radius": 1,
        "material": {"color": 0.8}})"),
        expected, 0.02 * expected);
}

TEST(FlatShapes, RectangleCoversItsProjectedArea) {
    const double half = 10 * std::tan(10 * std::numbers::pi / 180);
    const double expected = 2.0 * 1.0 / (4 * half * half);
    const double got =
        lit_fraction(R"({"type": "rectangle", "center": [0, 0, 0], "normal": [0, 0, 1],
        "size": [2, 1], "material": {"color": 0.8}})");
    EXPECT_NEAR(got, expected, 0.02 * expected);
}

}  // namespace
}  // namespace lenslab
