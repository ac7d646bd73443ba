// Whole renders: radiometry against closed forms, determinism across thread counts, cancel.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "math/constants.h"
#include "render/render_session.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

// A camera looking straight down at a diffuse floor (albedo 0.5) through a narrow field, so
// the centre pixel sees the point below the light.
// 256 samples: each carries 4 wavelengths, and a pixel's 1024 wavelengths are stratified, so
// a white light on a grey floor comes out grey to a fraction of a percent.
std::string floor_scene(const std::string& lights_and_objects, int spp = 256) {
    return R"({
      "camera": {"position": [0, 1, 0], "look_at": [0, 0, 0], "up": [0, 0, -1], "fov": 1},
      "render": {"width": 3, "height": 3, "spp": )" +
           std::to_string(spp) + R"(},
      "objects": [
        {"type": "triangle", "vertices": [[-50, 0, -50], [-50, 0, 50], [50, 0, 50]], "material": {"color": 0.5}},
        {"type": "triangle", "vertices": [[-50, 0, -50], [50, 0, 50], [50, 0, -50]], "material": {"color": 0.5}})" +
           lights_and_objects + "}";
}

double centre_radiance(const Scene& scene) {
    RenderControl control;
    const Film film = render_scene(scene, control).film;
    return film.at(1, 1).g;
}

TEST(Radiometry, PointLightGivesLambertRadiance) {
    // A point source of power P at height h: E = I / h^2 with I = P / (4 pi); a Lambertian
    // surface of albedo a then has radiance L = a E / pi (Lambert's cosine law).
    const double P = 100, h = 2;
    const Scene scene = parse_scene(
        floor_scene(R"(], "lights": [{"type": "point", "position": [0, 2, 0], "power": 100}])"));
    const double expected = 0.5 * (P / (4 * kPi) / (h * h)) / kPi;
    EXPECT_NEAR(centre_radiance(scene), expected, 5e-3 * expected);
}

TEST(Radiometry, WhiteFloorUnderWhiteLightIsNeutralGrey) {
    // D65 light (colour [1, 1, 1]) on a grey floor, rendered spectrally: r = g = b.
    const Scene scene = parse_scene(floor_scene(
        R"(], "lights": [{"type": "point", "position": [0, 2, 0], "power": 100, "spectrum": "d65"}])"));
    RenderControl control;
    const PixelRgb p = render_scene(scene, control).film.at(1, 1);
    EXPECT_NEAR(p.r / p.g, 1.0, 5e-3);
    EXPECT_NEAR(p.b / p.g, 1.0, 5e-3);
}

TEST(Radiometry, BeamGivesUniformIrradiance) {
    // A collimated beam of power P over a disc of radius r: E = P / (pi r^2) at normal
    // incidence.
    const Scene scene = parse_scene(floor_scene(
        R"(], "lights": [{"type": "beam", "origin": [0, 3, 0], "direction": [0, -1, 0], "radius": 0.5, "power": 2}])"));
    const double expected = 0.5 * (2 / (kPi * 0.25)) / kPi;
    EXPECT_NEAR(centre_radiance(scene), expected, 5e-3 * expected);
}

TEST(Radiometry, EmittingSphereMatchesTheSolidAngleFormula) {
    // A Lambertian sphere of radiance L and radius R whose centre is d above the point gives
    // E = pi L (R / d)^2 (the sphere subtends a cap with sin^2 of its half-angle = (R/d)^2).
    const double L = 50, R = 0.25, d = 2;
    const Scene scene = parse_scene(floor_scene(
        R"(, {"type": "sphere", "center": [0, 2, 0], "radius": 0.25,
             "material": {"color": 0, "emission": {"intensity": 50}}}])",
        256));
    const double expected = 0.5 * (kPi * L * (R / d) * (R / d)) / kPi;
    EXPECT_NEAR(centre_radiance(scene), expected, 0.01 * expected);
}

TEST(Radiometry, ShadowedPointSeesNoDirectLight) {
    const Scene scene = parse_scene(floor_scene(
        R"(, {"type": "sphere", "center": [0, 1.5, 0], "radius": 0.2, "material": {"color": 0.5}}],
           "lights": [{"type": "point", "position": [0, 2, 0], "power": 100}])"));
    EXPECT_EQ(centre_radiance(scene), 0.0);
}

TEST(RenderSession, SameSeedSameImageForAnyThreadCount) {
    const Scene scene = default_scene();
    Scene small = scene;
    small.render.width = 48;
    small.render.height = 36;
    small.render.spp = 2;
    RenderControl c1, c2;
    const Film one = render_scene(small, c1, 1).film;
    const Film two = render_scene(small, c2, 2).film;
    for (size_t i = 0; i < one.pixels().size(); ++i) {
        ASSERT_EQ(one.pixels()[i].r, two.pixels()[i].r);
        ASSERT_EQ(one.pixels()[i].g, two.pixels()[i].g);
        ASSERT_EQ(one.pixels()[i].b, two.pixels()[i].b);
    }
}

TEST(RenderSession, CancelStopsEarly) {
    Scene scene = default_scene();
    scene.render.width = 64;
    scene.render.height = 64;
    RenderControl control;
    control.cancel();
    EXPECT_TRUE(render_scene(scene, control).cancelled);
}

TEST(RenderSession, CancelDuringARenderStopsIt) {
    Scene scene = default_scene();
    scene.render.integrator = "whitted";
    scene.render.width = 256;
    scene.render.height = 256;
    RenderControl* self = nullptr;
    RenderControl control([&](double) { self->cancel(); });  // cancel after the first tile
    self = &control;
    const RenderResult r = render_scene(scene, control, 1);
    EXPECT_TRUE(r.cancelled);
    size_t black = 0;
    for (const PixelRgb& p : r.film.pixels()) black += p.r == 0 && p.g == 0 && p.b == 0;
    EXPECT_GT(black, r.film.pixels().size() / 2);  // most of the image was never rendered
}

TEST(RenderSession, ProgressReachesOne) {
    Scene scene = default_scene();
    scene.render.width = 40;
    scene.render.height = 40;
    scene.render.spp = 1;
    double last = 0;
    RenderControl control([&](double f) { last = f; });
    render_scene(scene, control);
    EXPECT_DOUBLE_EQ(last, 1.0);
}

TEST(RenderSession, ProgressNeverGoesBackwards) {
    // Workers compute their fraction before taking the lock, so a slower one may report a
    // smaller fraction after a faster one has reported a larger (CI saw 1/9 after 1).
    std::vector<double> seen;
    RenderControl control([&](double f) { seen.push_back(f); });
    control.report(0.5);
    control.report(1.0 / 9.0);
    control.report(1.0);
    control.report(0.25);
    EXPECT_EQ(seen, (std::vector<double>{0.5, 0.5, 1.0, 1.0}));
}

TEST(RenderSession, DefaultSceneIsTheReportsExperiment) {
    // Two transparent objects (a sphere and a lens), an opaque sphere, an emitting sphere
    // and a floor of triangles.
    const Scene scene = default_scene();
    int glass_spheres = 0, lenses = 0, opaque_spheres = 0, triangles = 0;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const Material& m = scene.material_of(static_cast<int>(i));
        switch (scene.objects[i].type) {
            case ObjectType::Sphere:
                if (m.transparency > 0)
                    ++glass_spheres;
                else if (!m.is_emitter())
                    ++opaque_spheres;
                break;
            case ObjectType::Lens:
                lenses += m.transparency > 0;
                break;
            case ObjectType::Triangle:
                ++triangles;
                break;
            case ObjectType::Mesh:
                break;
            case ObjectType::Implicit:
                ADD_FAILURE() << "the report had no implicit solids";
                break;
            case ObjectType::Disc:
            case ObjectType::Rectangle:
            case ObjectType::Mirror:
                ADD_FAILURE() << "the report had no discs, rectangles or mirrors";
                break;
        }
    }
    EXPECT_EQ(glass_spheres, 1);
    EXPECT_EQ(lenses, 1);
    EXPECT_EQ(opaque_spheres, 1);
    EXPECT_EQ(scene.emitters().size(), 1u);
    EXPECT_GE(triangles, 2);
}

}  // namespace
}  // namespace lenslab
