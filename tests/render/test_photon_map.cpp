// Photon maps against physics: irradiance of a point light, Fresnel transmission through a
// lens, the focus of a ball lens and of a thick lens (convergence with the photon count:
// test_photon_convergence.cpp).

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <sstream>

#include "math/constants.h"
#include "render/integrators/photon_map.h"
#include "render/photon_tracer.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

std::string floor_triangles(double y, double half = 50) {
    std::ostringstream s;
    s << R"({"name": "floor", "type": "triangle", "vertices": [[-H, Y, -H], [-H, Y, H], [H, Y, H]], "material": {"color": 0.5}},
            {"name": "floor", "type": "triangle", "vertices": [[-H, Y, -H], [H, Y, H], [H, Y, -H]], "material": {"color": 0.5}})";
    std::string t = s.str();
    for (auto [key, v] : {std::pair{"H", half}, std::pair{"Y", y}}) {
        for (size_t at; (at = t.find(key)) != std::string::npos;)
            t.replace(at, 1, std::to_string(v));
    }
    return t;
}

// A screen: the plane z = `z`, facing -z, 60 across.
std::string screen_at(double z) {
    std::ostringstream s;
    s << R"({"name": "screen", "type": "triangle", "vertices": [[-30, -30, )" << z << "], [30, 30, "
      << z << "], [30, -30, " << z << R"(]], "material": {"color": 0.5}},
         {"name": "screen", "type": "triangle", "vertices": [[-30, -30, )"
      << z << "], [-30, 30, " << z << "], [30, 30, " << z << R"(]], "material": {"color": 0.5}})";
    return s.str();
}

PhotonMap trace(const Scene& scene, int64_t photons, PhotonTracingStats* stats = nullptr) {
    RenderControl control;
    PhotonTracingSettings settings;
    settings.photons_per_light = photons;
    return trace_photons(scene, settings, control, stats);
}

double total_power(const PhotonKdTree& map) {
    double sum = 0;
    for (const Photon& p : map) sum += p.power[1];
    return sum;
}

TEST(PhotonMap, PointLightIrradianceMatchesInverseSquareLaw) {
    // E = I cos(theta) / r^2, I = P / (4 pi), on a floor 1 below a point light of P = 100 W.
    const Scene scene = parse_scene(R"({"camera": {"position": [0, 5, 5], "look_at": [0, 0, 0]},
        "objects": [)" + floor_triangles(0) +
                                    R"(],
        "lights": [{"type": "point", "position": [0, 1, 0], "power": 100}]})");
    const PhotonMap map = trace(scene, 4000000);
    GatherSettings g;
    g.radius = 0.1;
    g.max_photons = 1000000;
    std::vector<PhotonNeighbour> scratch;
    for (double x : {0.0, 0.3, 0.6, 0.9, 1.2}) {
        const double z = 0.1 * x;  // off the symmetry axes
        const double r2 = 1 + x * x + z * z, cos_theta = 1 / std::sqrt(r2);
        const double expected = 100 / (4 * kPi) * cos_theta / r2;
        const Rgb e = PhotonMap::irradiance(map.direct(), {x, 0, z}, {0, 1, 0}, g, scratch);
        std::printf("x = %.1f: E = %.4f, expected %.4f (%+.2f%%)\n", x, e.g, expected,
                    100 * (e.g / expected - 1));
        EXPECT_NEAR(e.g, expected, 0.03 * expected) << "x = " << x;
    }
}

TEST(PhotonMap, LensTransmitsTheFresnelShareOfABeam) {
    // Near-normal incidence on n = 1.5: each face transmits 1 - 0.04, so the screen behind
    // receives 0.96^2 = 0.9216 of the beam (plus 0.9216 * 0.04^2 from one internal
    // round trip: T^2 / (1 - R^2) = 0.9231 in all; Hecht section 4.6.2).
    const Scene scene = parse_scene(R"({"camera": {"position": [0, 0, -100], "look_at": [0, 0, 0]},
        "objects": [{"type": "lens", "center": [0, 0, 0], "axis": [0, 0, 1], "thickness": 5, "diameter": 25,
                     "front": {"shape": "sphere", "radius": 50}, "back": {"shape": "sphere", "radius": -50},
                     "material": {"transparency": 1, "ior": 1.5}}, )" +
                                    screen_at(10) + R"(],
        "lights": [{"type": "beam", "origin": [0, 0, -20], "direction": [0, 0, 1], "radius": 2, "power": 1}]})");
    PhotonTracingStats stats;
    const PhotonMap map = trace(scene, 400000, &stats);
    EXPECT_EQ(map.direct().size(), 0u);  // every photon reaching the screen went through glass
    EXPECT_NEAR(total_power(map.caustic()), 0.9216, 0.01 * 0.9216);
    EXPECT_NEAR(total_power(map.caustic()), 0.96 * 0.96 / (1 - 0.04 * 0.04), 0.003);
}

// Caustic irradiance at the axis of a screen placed at z, for a beam along +z.
double axial_caustic(const std::string& optics, double beam_radius, double z, double gather) {
    const Scene scene = parse_scene(R"({"camera": {"position": [0, 0, -100], "look_at": [0, 0, 0]},
        "objects": [)" + optics + ", " +
                                    screen_at(z) + R"(],
        "lights": [{"type": "beam", "origin": [0, 0, -60], "direction": [0, 0, 1], "radius": )" +
                                    std::to_string(beam_radius) + R"(, "power": 1}]})");
    const PhotonMap map = trace(scene, 60000);
    GatherSettings g;
    g.radius = gather;
    g.max_photons = 1000000;
    std::vector<PhotonNeighbour> scratch;
    return PhotonMap::irradiance(map.caustic(), {0, 0, z}, {0, 0, -1}, g, scratch).g;
}

// Screen position (scanned from z0 to z1) where the axial caustic is brightest.
double brightest_screen(const std::string& optics, double beam_radius, double z0, double z1,
                        int steps, double gather) {
    double best_z = z0, best = -1;
    for (int i = 0; i <= steps; ++i) {
        const double z = z0 + (z1 - z0) * i / steps;
        const double e = axial_caustic(optics, beam_radius, z, gather);
        if (e > best) {
            best = e;
            best_z = z;
        }
    }
    return best_z;
}

TEST(PhotonMap, BallLensFocusesAtItsBackFocalDistance) {
    // Ball lens: EFL = n D / (4 (n - 1)), back focal distance EFL - D/2 from the ball's back
    // surface (e.g. Edmund Optics, "Understanding Ball Lenses"). D = 2, n = 1.5: EFL = 1.5,
    // BFD = 0.5. A narrow beam (radius 0.15) keeps spherical aberration under 1% of BFD.
    const std::string ball = R"({"type": "sphere", "center": [0, 0, 0], "radius": 1,
                                 "material": {"transparency": 1, "ior": 1.5}})";
    const double n = 1.5, d = 2, efl = n * d / (4 * (n - 1)), bfd = efl - d / 2;
    const double z = brightest_screen(ball, 0.15, 1.40, 1.60, 40, 0.003);
    EXPECT_NEAR(z - 1.0, bfd, 0.02 * bfd);
}

TEST(PhotonMap, ThickLensFocusesAtItsBackFocalDistance) {
    // R1 = 50, R2 = -50, d = 5, n = 1.5: BFD = 49.15 behind the back vertex (z = 2.5), from
    // the thick-lens equation (Hecht eqs. 6.2, 6.3).
    const std::string lens =
        R"({"type": "lens", "center": [0, 0, 0], "axis": [0, 0, 1], "thickness": 5,
        "diameter": 25, "front": {"shape": "sphere", "radius": 50}, "back": {"shape": "sphere", "radius": -50},
        "material": {"transparency": 1, "ior": 1.5}})";
    const double f = 1 / (0.5 * (2.0 / 50 - 0.5 * 5 / (1.5 * 2500))),
                 bfd = f * (1 - 0.5 * 5 / (1.5 * 50));
    // Steps of 0.5% of the BFD: a quarter of the tolerance.
    const double z = brightest_screen(lens, 1.5, 2.5 + bfd * 0.95, 2.5 + bfd * 1.05, 20, 0.01);
    EXPECT_NEAR(z - 2.5, bfd, 0.02 * bfd);
}

TEST(PhotonMap, BrightnessDoesNotDependOnThePhotonCount) {
    const Scene scene = parse_scene(R"({"camera": {"position": [0, 5, 5], "look_at": [0, 0, 0]},
        "objects": [)" + floor_triangles(0, 2) +
                                    R"(],
        "lights": [{"type": "point", "position": [0, 1, 0], "power": 100}]})");
    // The floor (4 x 4, 1 below the light) catches the same share of the power whatever the
    // count: the solid angle of the square seen from the light.
    const double few = total_power(trace(scene, 20000).direct());
    const double many = total_power(trace(scene, 400000).direct());
    EXPECT_NEAR(few, many, 0.03 * many);
}

TEST(PhotonMap, SameMapsForAnyThreadCount) {
    const Scene scene = default_scene();
    auto run = [&](int threads) {
        tbb::task_arena arena(threads);
        PhotonMap map;
        arena.execute([&] { map = trace(scene, 50000); });
        return map;
    };
    const PhotonMap one = run(1), two = run(2);
    ASSERT_EQ(one.direct().size(), two.direct().size());
    ASSERT_EQ(one.caustic().size(), two.caustic().size());
    for (size_t i = 0; i < one.caustic().size(); ++i) {
        ASSERT_EQ(one.caustic().begin()[i].position[0], two.caustic().begin()[i].position[0]);
        ASSERT_EQ(one.caustic().begin()[i].power[1], two.caustic().begin()[i].power[1]);
    }
}

TEST(PhotonMap, RefusesAPhotonCountThatCannotFit) {
    const Scene scene = default_scene();
    RenderControl control;
    PhotonTracingSettings s;
    s.photons_per_light = int64_t{1} << 40;  // 32 TiB of photons
    try {
        trace_photons(scene, s, control);
        FAIL() << "no error";
    } catch (const ResourceError& e) {
        EXPECT_NE(std::string(e.what()).find("use fewer photons"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace lenslab
