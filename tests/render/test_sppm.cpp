// Stochastic progressive photon mapping against the unbiased path tracer, against closed
// forms (an integrating sphere, Fresnel transmission of a pane and of a dispersive slab),
// and against itself (convergence, determinism, no light through thin objects).

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "math/constants.h"
#include "render/progressive_render.h"
#include "render/render_session.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

struct Box {
    int x0, y0, x1, y1;  // pixels [x0, x1) x [y0, y1)
};

double mean_luminance(const Film& f, const Box& b) {
    double sum = 0;
    for (int y = b.y0; y < b.y1; ++y) {
        for (int x = b.x0; x < b.x1; ++x) sum += luminance(f.at(x, y));
    }
    return sum / ((b.x1 - b.x0) * (b.y1 - b.y0));
}

Box whole(const Film& f) { return {0, 0, f.width(), f.height()}; }

Rgb average(const Film& f) {
    Rgb sum;
    for (const PixelRgb& p : f.pixels()) sum += Rgb{p.r, p.g, p.b};
    return sum * (1.0 / static_cast<double>(f.pixels().size()));
}

// Mean over blocks of 8 x 8 pixels of |a - b| / b, comparing the blocks' mean luminance:
// a local comparison, with the per-pixel noise of both images averaged down.
double block_difference(const Film& a, const Film& b) {
    constexpr int kBlock = 8;
    double sum = 0;
    int n = 0;
    for (int y = 0; y + kBlock <= a.height(); y += kBlock) {
        for (int x = 0; x + kBlock <= a.width(); x += kBlock) {
            const Box box{x, y, x + kBlock, y + kBlock};
            const double mb = mean_luminance(b, box);
            sum += std::abs(mean_luminance(a, box) - mb) / mb;
            ++n;
        }
    }
    return sum / n;
}

double relative_difference(double a, double b) { return std::abs(a - b) / b; }

// Pixel where the point `p` appears through the scene's pinhole camera.
void project(const Scene& s, const Vec3& p, double& px, double& py) {
    const Vec3 f = normalize(s.camera.direction);
    const Vec3 r = normalize(cross(f, s.camera.up));
    const Vec3 u = cross(r, f);
    const Vec3 d = p - s.camera.position;
    const double half_h = std::tan(0.5 * s.camera.fov_deg * kPi / 180.0);
    const double half_w = half_h * s.render.width / s.render.height;
    px = (dot(d, r) / dot(d, f) / half_w + 1.0) * 0.5 * s.render.width;
    py = (1.0 - dot(d, u) / dot(d, f) / half_h) * 0.5 * s.render.height;
}

Scene caustic_room(int size) {
    Scene s = load_scene_file(LENSLAB_SOURCE_DIR "/scenes/caustic_room.json");
    s.render.width = s.render.height = size;
    return s;
}

RenderResult render(Scene s, const std::string& integrator, int threads = 0) {
    s.render.integrator = integrator;
    RenderControl control;
    return render_scene(s, control, threads);
}

bool same_pixels(const Film& a, const Film& b) {
    for (size_t i = 0; i < a.pixels().size(); ++i) {
        if (a.pixels()[i].r != b.pixels()[i].r || a.pixels()[i].g != b.pixels()[i].g ||
            a.pixels()[i].b != b.pixels()[i].b) {
            return false;
        }
    }
    return true;
}

// Pixels around the caustic room's caustic: where the line from the light through the glass
// sphere's centre meets the floor (the ball lens images the light just above the floor).
Box sppm_caustic_box(int size) {
    const Scene s = caustic_room(size);
    const Vec3 light = s.objects.back().shape->bounds().centre();
    const Vec3 glass = s.objects[s.objects.size() - 2].shape->bounds().centre();
    const Vec3 on_floor = light + (glass - light) * (light.y / (light.y - glass.y));
    double x, y;
    project(s, on_floor, x, y);
    return {int(x) - 3, int(y) - 3, int(x) + 4, int(y) + 4};
}

// The caustic room (scenes/caustic_room.json: a closed diffuse room, an emitting sphere and
// a glass sphere) at 64 x 64: one path-traced reference and one sppm run with the image kept
// after 1, 8, 64 and 128 passes. One test, three checks: the reference is most of its cost
// (seconds, and a minute under the sanitizers), and each test runs in a process of its own.
TEST(SppmAgainstPath, AgreesWithThePathTracerAndConverges) {
    constexpr int kSize = 64;
    constexpr int kSnapshots[] = {1, 8, 64, 128};
    Scene s = caustic_room(kSize);
    s.render.spp = 512;
    const Film path = render(s, "path").film;
    s.render.integrator = "sppm";
    s.render.pass_photons = 5000;
    ProgressiveRender progressive(s);
    std::vector<Film> sppm;
    RenderControl control;
    for (int target : kSnapshots) {
        while (progressive.passes() < target) progressive.add_pass(control);
        sppm.push_back(progressive.image());
    }
    const Box caustic = sppm_caustic_box(kSize);

    {
        SCOPED_TRACE("the caustic box is a caustic");
        // Most of the light in the box comes through the glass: with the sphere made of black
        // paint instead (the same shadow, no caustic) the path tracer finds it much darker.
        Scene black = caustic_room(kSize);
        black.render.spp = 64;
        for (Material& m : black.materials) {
            if (m.transparency == 0) continue;
            m.transparency = 0;
            m.color = {0, 0, 0};
            m.finish();
        }
        EXPECT_GT(mean_luminance(path, caustic),
                  2.0 * mean_luminance(render(black, "path").film, caustic));
    }
    {
        SCOPED_TRACE("agrees with the path tracer");
        // Both integrators solve the same light transport (direct light, interreflection, the
        // caustic seen directly and through the glass): after enough passes and samples their
        // images agree within 3%: over the whole image, in the caustic, and block by block.
        const Film& last = sppm.back();
        EXPECT_LT(relative_difference(mean_luminance(last, whole(last)),
                                      mean_luminance(path, whole(path))),
                  0.03);
        EXPECT_LT(relative_difference(mean_luminance(last, caustic), mean_luminance(path, caustic)),
                  0.03);
        EXPECT_LT(block_difference(last, path), 0.03);
    }
    {
        SCOPED_TRACE("the error falls as passes grow");
        std::vector<double> error;
        for (const Film& f : sppm) error.push_back(block_difference(f, path));
        for (size_t i = 1; i < error.size(); ++i) {
            EXPECT_LT(error[i], error[i - 1]) << "after " << kSnapshots[i] << " passes";
        }
    }
}

TEST(Sppm, ProgressiveRenderGivesTheSameImageAsARender) {
    Scene s = caustic_room(24);
    s.render.integrator = "sppm";
    s.render.passes = 3;
    s.render.pass_photons = 5000;
    ProgressiveRender progressive(s, 1);
    RenderControl control;
    for (int i = 0; i < 3; ++i) ASSERT_TRUE(progressive.add_pass(control));
    EXPECT_TRUE(same_pixels(progressive.image(), render(s, "sppm", 2).film));
}

TEST(Sppm, SameImageForAnyThreadCount) {
    Scene s = caustic_room(32);
    s.render.passes = 3;
    s.render.pass_photons = 8000;
    EXPECT_TRUE(same_pixels(render(s, "sppm", 1).film, render(s, "sppm", 2).film));
}

TEST(Path, SameImageForAnyThreadCount) {
    Scene s = caustic_room(32);
    s.render.spp = 2;
    EXPECT_TRUE(same_pixels(render(s, "path", 1).film, render(s, "path", 2).film));
}

// A camera 0.5 from the centre of a closed diffuse sphere of radius 1 (albedo a = 0.5),
// looking at its wall, with a point light of power P at the centre.
std::string integrating_sphere(int spp) {
    return R"({"camera": {"position": [0, 0, 0.5], "look_at": [0, 0, -1], "fov": 1},
      "render": {"width": 3, "height": 3, "spp": )" +
           std::to_string(spp) + R"(, "max_depth": 64,
                 "pass_photons": 50000, "passes": 16, "initial_radius": 0.08},
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": {"color": 0.5}}],
      "lights": [{"type": "point", "position": [0, 0, 0], "power": 100}]})";
}

// Integrating-sphere theory (Goebel 1967, "Generalized integrating-sphere theory", Appl.
// Opt. 6(1); Labsphere, "A guide to integrating sphere theory and applications"): every
// diffuse reflection inside a sphere spreads its light uniformly over the wall, so the wall
// irradiance is the direct E0 = P / (4 pi R^2) times 1 + a + a^2 + ... = 1 / (1 - a), and its
// radiance L = a E0 / (pi (1 - a)). Half of it (a = 0.5) is interreflected light.
double integrating_sphere_radiance() {
    const double a = 0.5, power = 100, radius = 1;
    return a * power / (4 * kPi * radius * radius) / (kPi * (1 - a));
}

TEST(Path, IntegratingSphereRadiance) {
    const Film f = render(parse_scene(integrating_sphere(1024)), "path").film;
    EXPECT_NEAR(mean_luminance(f, whole(f)), integrating_sphere_radiance(),
                0.02 * integrating_sphere_radiance());
}

TEST(Sppm, IntegratingSphereRadiance) {
    const Film f = render(parse_scene(integrating_sphere(1)), "sppm").film;
    EXPECT_NEAR(mean_luminance(f, whole(f)), integrating_sphere_radiance(),
                0.03 * integrating_sphere_radiance());
}

// A beam of power 2 and radius 0.5 straight down onto a floor of albedo 0.5 through
// `obstacle` above it; the camera looks down at the middle of the spot from `camera_y`.
std::string beam_through(const std::string& obstacle, double camera_y, int passes) {
    return R"({"camera": {"position": [0, )" + std::to_string(camera_y) +
           R"(, 0], "look_at": [0, 0, 0], "up": [0, 0, -1], "fov": 2},
      "render": {"width": 3, "height": 3, "max_depth": 32, "pass_photons": 40000, "initial_radius": 0.2,
                 "passes": )" +
           std::to_string(passes) + R"(, "integrator": "sppm"},
      "objects": [
        {"type": "triangle", "vertices": [[-5, 0, -5], [-5, 0, 5], [5, 0, 5]], "material": {"color": 0.5}},
        {"type": "triangle", "vertices": [[-5, 0, -5], [5, 0, 5], [5, 0, -5]], "material": {"color": 0.5}},
        )" +
           obstacle + R"(],
      "lights": [{"type": "beam", "origin": [0, 3, 0], "direction": [0, -1, 0], "radius": 0.5, "power": 2}]})";
}

// Radiance of the floor lit by the whole beam: a E / pi with E = P / (pi r^2).
constexpr double kBeamFloorRadiance = 0.5 * (2 / (kPi * 0.25)) / kPi;

TEST(Sppm, BeamThroughAPaneMatchesFresnel) {
    // An open transparent triangle pair is a thin pane (n = 1.5): at normal incidence each
    // face reflects R = ((n - 1) / (n + 1))^2 = 0.04 (Hecht, Optics, eq. 4.67), and the
    // incoherent sum over the pane's multiple reflections transmits T = 1 - 2R / (1 + R). The
    // light reaches the floor only through the pane, a caustic from a delta light (shadow
    // rays are blocked and a path tracer cannot find it): sppm finds it with its photons.
    const std::string pane =
        R"({"type": "triangle", "vertices": [[-1, 1.5, -1], [-1, 1.5, 1], [1, 1.5, 1]], "material": {"color": 1, "transparency": 1, "ior": 1.5}},
           {"type": "triangle", "vertices": [[-1, 1.5, -1], [1, 1.5, 1], [1, 1.5, -1]], "material": {"color": 1, "transparency": 1, "ior": 1.5}})";
    const double r = 0.04, t = 1 - 2 * r / (1 + r);
    const RenderResult result = render(parse_scene(beam_through(pane, 1.0, 16)), "sppm");
    const Film& f = result.film;
    EXPECT_NEAR(mean_luminance(f, whole(f)), kBeamFloorRadiance * t, 0.02 * kBeamFloorRadiance * t);
}

// A slab of N-BK7, 0.2 thick, between the beam and the floor.
const std::string kBk7Slab =
    R"({"type": "lens", "center": [0, 1.5, 0], "axis": [0, 1, 0], "thickness": 0.2, "diameter": 3,
        "front": {"shape": "flat"}, "back": {"shape": "flat"}, "material": {"color": 1, "transparency": 1, "glass": "N-BK7"}})";

// Transmission of the slab at normal incidence for n_d = 1.5168 (SCHOTT N-BK7 data sheet):
// each face reflects R = ((n - 1) / (n + 1))^2, and the incoherent sum over the reflections
// inside transmits T = (1 - R)^2 / (1 - R^2) = (1 - R) / (1 + R). n varies by 0.015 over the
// visible range, which moves T by 0.2%.
double bk7_slab_transmission() {
    const double n = 1.5168, r = (n - 1) * (n - 1) / ((n + 1) * (n + 1));
    return (1 - r) / (1 + r);
}

TEST(Sppm, BeamThroughADispersiveSlabSeenDirectly) {
    // The photons are dispersed (each at one wavelength) and the camera below the slab is
    // not: each photon is counted at its own wavelength. White light stays white.
    const Film f = render(parse_scene(beam_through(kBk7Slab, 1.0, 24)), "sppm").film;
    const double expected = kBeamFloorRadiance * bk7_slab_transmission();
    EXPECT_NEAR(mean_luminance(f, whole(f)), expected, 0.03 * expected);
    EXPECT_NEAR(f.at(1, 1).r / f.at(1, 1).g, 1.0, 0.03);
    EXPECT_NEAR(f.at(1, 1).b / f.at(1, 1).g, 1.0, 0.03);
}

TEST(Sppm, BeamThroughADispersiveSlabSeenThroughIt) {
    // The camera above looks through the slab too: camera paths and photons are both
    // dispersed and meet at each pass's shared wavelength; the light crosses the slab twice.
    // One wavelength per pass: the colour of a pixel whose camera path reflected off the
    // slab in some passes misses those passes' wavelengths, so 64 pixels are averaged.
    Scene s = parse_scene(beam_through(kBk7Slab, 2.5, 64));
    s.render.pass_photons = 20000;
    s.render.width = s.render.height = 8;
    const Film f = render(s, "sppm").film;
    const double t = bk7_slab_transmission();
    const double expected = kBeamFloorRadiance * t * t;
    EXPECT_NEAR(mean_luminance(f, whole(f)), expected, 0.03 * expected);
    const Rgb mean = average(f);
    EXPECT_NEAR(mean.r / mean.g, 1.0, 0.04);
    EXPECT_NEAR(mean.b / mean.g, 1.0, 0.04);
}

TEST(Sppm, NoLightThroughAThinSheet) {
    // The pane focuses nothing but sends the beam's photons onto the top of a sheet (two
    // triangles, no thickness); a camera below sees the sheet's underside, which no light
    // reaches. Photons on the top lie within the radius of the points underneath (at distance
    // zero): only the side they arrived on keeps them out.
    const std::string sheet_and_pane =
        R"({"type": "triangle", "vertices": [[-1, 1.5, -1], [-1, 1.5, 1], [1, 1.5, 1]], "material": {"color": 1, "transparency": 1, "ior": 1.5}},
           {"type": "triangle", "vertices": [[-1, 1.5, -1], [1, 1.5, 1], [1, 1.5, -1]], "material": {"color": 1, "transparency": 1, "ior": 1.5}},
           {"type": "triangle", "vertices": [[-1, 0.5, -1], [-1, 0.5, 1], [1, 0.5, 1]], "material": {"color": 0.5}},
           {"type": "triangle", "vertices": [[-1, 0.5, -1], [1, 0.5, 1], [1, 0.5, -1]], "material": {"color": 0.5}})";
    Scene above = parse_scene(beam_through(sheet_and_pane, 1.0, 2));
    Scene below = above;
    below.camera.position = {0, 0.2, 0};
    below.camera.direction = {0, 1, 0};
    const Film lit = render(above, "sppm").film;
    const Film unlit = render(below, "sppm").film;
    const double top = mean_luminance(lit, whole(lit));
    EXPECT_GT(top, 0.5 * kBeamFloorRadiance);
    // Light does reach the underside the long way round (reflected down by the pane's
    // underside past the sheet's edge, then up off the floor): at some seeds a photon or two,
    // 1e-4 of the top. Photons leaking through would light it like the top.
    EXPECT_LT(mean_luminance(unlit, whole(unlit)), 1e-3 * top);
}

// A camera 2 above a floor lit by a point light, looking straight down through a 1-degree
// field: every photon lands on the floor straight from the light (counted by shadow rays,
// not stored), so nothing shrinks the radii.
Scene point_lit_floor() {
    return parse_scene(
        R"({"camera": {"position": [0, 2, 0], "look_at": [0, 0, 0], "up": [0, 0, -1], "fov": 1},
      "render": {"width": 3, "height": 3, "integrator": "sppm", "passes": 2, "pass_photons": 1000},
      "objects": [
        {"type": "triangle", "vertices": [[-50, 0, -50], [-50, 0, 50], [50, 0, 50]], "material": {"color": 0.5}},
        {"type": "triangle", "vertices": [[-50, 0, -50], [50, 0, 50], [50, 0, -50]], "material": {"color": 0.5}}],
      "lights": [{"type": "point", "position": [0, 1, 0], "power": 10}]})");
}

TEST(Sppm, InitialRadiusIsTwoPixelFootprints) {
    // A pixel subtends 2 tan(fov / 2) / height radians; at distance 2 (to within 4e-5 over
    // this field) its footprint is 2 * that, and the radius starts at two footprints (the
    // cap, 0.5% of the scene's diagonal, is 0.7 here).
    const RenderResult r = render(point_lit_floor(), "sppm");
    const double footprint = 2.0 * (2.0 * std::tan(0.5 * kPi / 180.0) / 3.0);
    EXPECT_NEAR(r.stats.value("mean_radius"), 2.0 * footprint, 1e-4 * footprint);
    Scene given = point_lit_floor();
    given.render.initial_radius = 0.01;
    EXPECT_DOUBLE_EQ(render(given, "sppm").stats.value("mean_radius"), 0.01);
}

TEST(Sppm, TimeBudgetEndsTheRender) {
    Scene s = point_lit_floor();
    s.render.passes = 0;  // no pass limit
    s.render.time = 0.05;
    const RenderResult r = render(s, "sppm");
    EXPECT_FALSE(r.cancelled);
    EXPECT_GE(r.stats.passes, 1);
}

TEST(Sppm, CancelledRenderWritesNothing) {
    Scene s = caustic_room(16);
    s.render.integrator = "sppm";
    RenderControl control;
    control.cancel();
    EXPECT_TRUE(render_scene(s, control).cancelled);
}

}  // namespace
}  // namespace lenslab
