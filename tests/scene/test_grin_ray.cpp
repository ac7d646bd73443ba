#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <string>

#include "analysis/trace/ray_tree.h"
#include "scene/interaction.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

Scene grin_sphere_scene(const std::string& grin) {
    return parse_scene(R"({"camera": {"position": [0, 0, -5], "look_at": [0, 0, 0]},
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
                   "material": {"transparency": 1, "grin": )" +
                       grin + "}}]}");
}

// Where a ray that entered the only object at `entry` along `d` leaves it.
GrinExit grin_exit(const Scene& scene, const Vec3& entry, const Vec3& d) {
    const SceneObject& o = scene.objects[0];
    return trace_grin_ray(grin_medium_of(o, scene.materials[o.material], kLineD), *o.shape, entry,
                          d);
}

TEST(GrinRay, LuneburgLensFocusesAParallelBeamOnTheOppositeRim) {
    // Luneburg (1944): with n = sqrt(2 - r^2/R^2) every ray of a parallel beam reaches the
    // point of the sphere diametrically opposite the beam's entry side. Here R = 1, beam +z.
    const Scene scene = grin_sphere_scene(R"({"profile": "luneburg", "radius": 1})");
    double sum2 = 0;
    int rays = 0, steps = 0;
    for (double x = -0.9; x <= 0.91; x += 0.15) {
        for (double y = -0.9; y <= 0.91; y += 0.15) {
            if (x * x + y * y > 0.95 * 0.95) continue;
            // From outside: the rim has n = 1, so the ray enters unbent and unreflected.
            Interaction entry;
            ASSERT_TRUE(next_interaction(scene, {{x, y, -3}, {0, 0, 1}}, kLineD, entry));
            // (n at the computed hit point differs from 1 by rounding: R ~ 1e-17.)
            const Branch& in = entry.scattering.branches[entry.scattering.count - 1];
            EXPECT_EQ(in.event, Event::Refract);
            EXPECT_GT(in.weight, 1.0 - 1e-12);
            EXPECT_LT(length(in.direction - Vec3{0, 0, 1}), 1e-8);
            Interaction exit;
            ASSERT_TRUE(next_interaction(scene, {entry.point(), {0, 0, 1}}, kLineD, exit));
            ASSERT_GT(exit.grin_steps, 0);
            const Vec3 miss = exit.point() - Vec3{0, 0, 1};
            sum2 += dot(miss, miss);
            steps += exit.grin_steps;
            ++rays;
        }
    }
    const double rms = std::sqrt(sum2 / rays);
    EXPECT_LT(rms, 1e-4);  // R = 1
    std::cout << "Luneburg: " << rays << " rays, spot RMS " << rms << " R, " << double(steps) / rays
              << " steps per ray\n";
}

TEST(GrinRay, MaxwellFisheyeImagesARimPointToItsAntipode) {
    // Maxwell (1854): in n = n0 / (1 + r^2/R^2) the rays from a point meet again at the
    // inverted point -R^2 p / |p|^2; from a point on the sphere r = R, at its antipode.
    const Scene scene = grin_sphere_scene(R"({"profile": "fisheye", "n0": 2, "radius": 1})");
    const Vec3 source{1, 0, 0};
    for (double a : {0.0, 0.3, 0.7, 1.1, 1.4}) {
        for (double b : {0.0, 1.0, 2.5}) {
            const Vec3 d =
                normalize(Vec3{-std::cos(a), std::sin(a) * std::cos(b), std::sin(a) * std::sin(b)});
            const GrinExit exit = grin_exit(scene, source, d);
            ASSERT_TRUE(exit.left);
            EXPECT_LT(length(exit.hit.point - Vec3{-1, 0, 0}), 1e-6) << a << " " << b;
        }
    }
}

std::string grin_number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

// A GRIN rod along +z from z = 0 to `length`, diameter 2: n = n0 (1 - A r^2 / 2).
Scene grin_rod_scene(double length, double A) {
    const std::string l = grin_number(length);
    return parse_scene(R"({"camera": {"position": [0, 0, -5], "look_at": [0, 0, 0]},
      "objects": [{"type": "lens", "center": [0, 0, )" +
                       grin_number(length / 2) + R"(], "axis": [0, 0, 1], "thickness": )" + l +
                       R"(, "diameter": 2, "front": {"shape": "flat"}, "back": {"shape": "flat"},
        "material": {"transparency": 1,
                     "grin": {"profile": "radial", "n0": 1.6, "A": )" +
                       grin_number(A) + "}}}]}");
}

TEST(GrinRay, ParabolicRodOscillatesWithPitchTwoPiOverRootA) {
    // Paraxial rays in n = n0 (1 - A r^2 / 2) obey r'' = -A r: r = h cos(sqrt(A) z), pitch
    // 2 pi / sqrt(A) (Gomez-Reino, Perez and Bao, Gradient-Index Optics, 2002, ch. 2). A ray
    // parallel to the axis at height h crosses it at z = (2k + 1) P / 4; a pitch off by a
    // relative e would leave it at |x| = h (2k + 1) pi / 2 e there.
    const double A = 0.25, pitch = 2 * std::numbers::pi / std::sqrt(A), h = 0.002;
    for (int k : {0, 1, 2}) {
        const double length = (2 * k + 1) * pitch / 4;
        const Scene scene = grin_rod_scene(length, A);
        const GrinExit exit = grin_exit(scene, {h, 0, 0}, {0, 0, 1});
        ASSERT_TRUE(exit.left);
        EXPECT_NEAR(exit.hit.point.z, length, 1e-9);
        EXPECT_LT(std::abs(exit.hit.point.x) / h, (2 * k + 1) * std::numbers::pi / 2 * 1e-4) << k;
    }
}

TEST(GrinRay, QuarterPitchRodFocusesACollimatedBeamOnItsBackFace) {
    const double A = 0.25, quarter = std::numbers::pi / (2 * std::sqrt(A));
    const Scene scene = grin_rod_scene(quarter, A);
    for (double h : {0.001, 0.003, 0.005}) {
        for (double phi : {0.0, 2.0, 4.0}) {
            // Through the front face at normal incidence, then the rod.
            const RayTree tree =
                trace_ray_tree(scene, {{h * std::cos(phi), h * std::sin(phi), -1}, {0, 0, 1}}, {});
            const RayTreeNode* in = nullptr;
            for (const auto& c : tree.root.children)
                if (c.event == Event::Refract) in = &c;
            ASSERT_NE(in, nullptr);
            const RayTreeNode* out = nullptr;
            for (const auto& c : in->children)
                if (c.event == Event::Refract) out = &c;
            ASSERT_NE(out, nullptr);
            ASSERT_GT(out->path.size(), 2u);  // the curved path, for `trace`
            EXPECT_EQ(out->steps + 1, int(out->path.size()));
            EXPECT_NEAR(out->to->z, quarter, 1e-9);
            // On the axis within the paraxial aberration, O(A h^2) of h.
            EXPECT_LT(std::hypot(out->to->x, out->to->y), 1e-4 * h);
        }
    }
}

TEST(GrinRay, DispersionScalesTheProfileByTheGlassIndexOverItsDLineIndex) {
    // The documented model (docs/grin.md): n(p, lambda) = profile(p) n_glass(lambda) / n_d.
    // With N-BK7 (SCHOTT: n_d = 1.5168, n_F = 1.52238) the Luneburg rim is 1 at the d line only.
    const Scene scene = parse_scene(R"({"camera": {"position": [0, 0, -5], "look_at": [0, 0, 0]},
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": {"transparency": 1,
                   "glass": "N-BK7", "grin": {"profile": "luneburg", "radius": 1}}}]})");
    const SceneObject& o = scene.objects[0];
    const Material& m = scene.materials[o.material];
    EXPECT_DOUBLE_EQ(grin_medium_of(o, m, kLineD).index({0, 0, 1}), 1.0);
    EXPECT_NEAR(grin_medium_of(o, m, kLineF).index({0, 0, 1}), 1.52238 / 1.5168, 2e-5);
    EXPECT_NEAR(grin_medium_of(o, m, kLineF).index({0, 0, 0}), std::sqrt(2.0) * 1.52238 / 1.5168,
                3e-5);
}

void expect_same_tree(const RayTreeNode& a, const RayTreeNode& b) {
    ASSERT_EQ(a.children.size(), b.children.size());
    EXPECT_EQ(a.event, b.event);
    EXPECT_NEAR(a.weight, b.weight, 1e-12);
    ASSERT_EQ(a.to.has_value(), b.to.has_value());
    if (a.to) {
        EXPECT_LT(length(*a.to - *b.to), 1e-12);
    }
    EXPECT_LT(length(a.direction - b.direction), 1e-12);
    for (size_t i = 0; i < a.children.size(); ++i) expect_same_tree(a.children[i], b.children[i]);
}

TEST(GrinRay, UniformFormulaTracesLikePlainGlass) {
    const Scene glass = parse_scene(R"({"camera": {"position": [0, 0, -5], "look_at": [0, 0, 0]},
      "objects": [{"type": "sphere", "center": [0.1, 0, 0], "radius": 1,
                   "material": {"transparency": 1, "ior": 1.5}}]})");
    const Scene grin = parse_scene(R"({"camera": {"position": [0, 0, -5], "look_at": [0, 0, 0]},
      "objects": [{"type": "sphere", "center": [0.1, 0, 0], "radius": 1,
                   "material": {"transparency": 1, "grin": {"profile": "formula",
                                "formula": "1.5"}}}]})");
    for (double x : {0.0, 0.3, 0.6, 0.9}) {
        const Ray ray{{x, 0.2, -4}, normalize(Vec3{0.05, 0, 1})};
        const RayTreeOptions options{8, 1e-9};
        expect_same_tree(trace_ray_tree(glass, ray, options).root,
                         trace_ray_tree(grin, ray, options).root);
    }
}

}  // namespace
}  // namespace lenslab
