// A glass prism on the optical bench: the path of one ray worked out by hand, and the
// minimum deviation of an equilateral prism, D = 2 asin(n sin(A/2)) - A (Hecht, Optics,
// section 5.5.1), found by scanning the angle of incidence as a spectrometer user would.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "analysis/trace/ray_tree.h"
#include "optics/glass.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Apex 60 degrees, sides 1, n = 1.5 (one index for all colours), long axis +y, apex towards
// +z: the refracting faces meet at the apex edge x = 0, z = cos(30)/2; the left one runs down
// to x = -1/2, the right one to x = +1/2, and the base lies at z = -cos(30)/2.
Scene equilateral_prism() {
    return parse_scene(R"({
      "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
      "objects": [{"name": "prism", "type": "prism", "apex_angle": 60, "side": 1, "height": 1,
                   "center": [0, 0, 0], "axis": [0, 1, 0], "facing": [0, 0, 1],
                   "material": {"color": 1, "transparency": 1, "ior": 1.5}}]})");
}

// Follows the refracted branch into and out of the prism; the final direction, or nothing if
// the ray did not go in through one face and out through another.
std::optional<Vec3> through_both_faces(const Scene& scene, const Ray& ray, Vec3* entry = nullptr,
                                       Vec3* exit = nullptr, double wavelength_nm = kLineD) {
    RayTreeOptions options;
    options.wavelength_nm = wavelength_nm;
    const RayTree tree = trace_ray_tree(scene, ray, options);
    const RayTreeNode* node = &tree.root;
    for (int face = 0; face < 2; ++face) {
        const RayTreeNode* refracted = nullptr;
        for (const RayTreeNode& c : node->children) {
            if (c.event == Event::Refract) refracted = &c;
        }
        if (!refracted) return std::nullopt;
        if (face == 0 && entry) *entry = *refracted->to;
        if (face == 1 && exit) *exit = *refracted->to;
        node = refracted;
    }
    // Leaves the scene.
    if (node->children.size() != 1 || node->children[0].event != Event::Escape) return std::nullopt;
    return node->direction;
}

TEST(Prism, OneRayWorkedOutByHand) {
    const Scene scene = equilateral_prism();
    // A ray along +x at z = 0 meets the left face at its middle, (-1/4, 0, 0), at 30 degrees
    // from the face's outward normal (-cos 30, 0, sin 30).
    const Ray ray{{-2, 0, 0}, {1, 0, 0}};
    SceneHit hit;
    ASSERT_TRUE(scene.intersect(ray, 0, INFINITY, hit));
    EXPECT_NEAR(hit.surface.t, 1.75, 1e-12);
    EXPECT_NEAR(length(hit.surface.normal - Vec3{-std::cos(30 * kDeg), 0, 0.5}), 0.0, 1e-12);

    // Snell: sin(t2) = sin(30) / 1.5; inside, the ray runs 30 - t2 below +x (towards the
    // base); it meets the right face at t3 = 60 - t2 from its normal and leaves at t4 with
    // sin(t4) = 1.5 sin(t3), t4 - 30 below +x: the deviation t1 + t4 - A.
    const double t2 = std::asin(0.5 / 1.5);
    const double t3 = 60 * kDeg - t2;
    const double t4 = std::asin(1.5 * std::sin(t3));
    const double inside = 30 * kDeg - t2;
    // Distance inside: from the left face's plane to the right face's, along the ray.
    const double half_d = std::cos(30 * kDeg) / 2;
    const double s = 2 * half_d * std::sin(30 * kDeg) / std::cos(t3);
    const Vec3 expected_exit = Vec3{-0.25, 0, 0} + Vec3{std::cos(inside), 0, -std::sin(inside)} * s;

    Vec3 entry, exit;
    const auto out = through_both_faces(scene, ray, &entry, &exit);
    ASSERT_TRUE(out.has_value());
    EXPECT_NEAR(length(entry - Vec3{-0.25, 0, 0}), 0.0, 1e-12);
    EXPECT_NEAR(length(exit - expected_exit), 0.0, 1e-12);
    const double deviation = t4 - 30 * kDeg;  // = 30 + t4 - 60
    EXPECT_NEAR(length(*out - Vec3{std::cos(deviation), 0, -std::sin(deviation)}), 0.0, 1e-12);
    EXPECT_NEAR(deviation / kDeg, 47.10, 0.01);  // t4 = 77.10 degrees
}

// Minimum deviation found by scanning the incidence on the left face's middle, as with a
// spectrometer: coarse 0.05 degree steps, then 0.0005 degree steps around the best. Rays hit
// the middle of the left face at incidence i; the face's inward normal points 30 degrees
// below +x, so the ray points 30 - i below +x. Returns {deviation, incidence} in degrees.
std::pair<double, double> scanned_minimum_deviation(const Scene& scene,
                                                    double wavelength_nm = kLineD) {
    auto deviation = [&](double i) {
        const Vec3 d{std::cos(30 * kDeg - i), 0, -std::sin(30 * kDeg - i)};
        const auto out = through_both_faces(scene, {Vec3{-0.25, 0, 0} - d * 2.0, d}, nullptr,
                                            nullptr, wavelength_nm);
        return out ? std::acos(std::clamp(dot(*out, d), -1.0, 1.0)) : INFINITY;
    };
    double best_i = 0, best = INFINITY;
    for (double i = 30 * kDeg; i <= 80 * kDeg; i += 0.05 * kDeg) {
        if (const double dev = deviation(i); dev < best) {
            best = dev;
            best_i = i;
        }
    }
    for (double i = best_i - 0.05 * kDeg; i <= best_i + 0.05 * kDeg; i += 0.0005 * kDeg) {
        if (const double dev = deviation(i); dev < best) {
            best = dev;
            best_i = i;
        }
    }
    return {best / kDeg, best_i / kDeg};
}

TEST(Prism, MinimumDeviationOfAnEquilateralPrism) {
    const Scene scene = equilateral_prism();
    const double n = 1.5, apex = 60 * kDeg;
    const double expected = 2 * std::asin(n * std::sin(apex / 2)) - apex;  // 37.18 degrees
    const auto [best, best_i] = scanned_minimum_deviation(scene);
    EXPECT_NEAR(best, 37.18, 0.01);
    EXPECT_NEAR(best, expected / kDeg, 0.01);
    // At minimum deviation the ray passes symmetrically: incidence asin(n sin(A/2)) = 48.59.
    EXPECT_NEAR(best_i, std::asin(n * std::sin(apex / 2)) / kDeg, 0.1);
}

TEST(Prism, NBk7MinimumDeviationAtTheFraunhoferLines) {
    // An equilateral N-BK7 prism at the F, d and C lines: D = 2 asin(n sin 30) - 60 with n
    // from the SCHOTT data sheet's Sellmeier formula (n_F 1.52238, n_d 1.51680, n_C 1.51432).
    const Scene scene = parse_scene(R"({
      "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
      "objects": [{"type": "prism", "apex_angle": 60, "side": 1, "height": 1, "center": [0, 0, 0],
                   "axis": [0, 1, 0], "facing": [0, 0, 1],
                   "material": {"transparency": 1, "glass": "N-BK7"}}]})");
    const IndexModel& bk7 = *find_glass("N-BK7")->model;
    double previous = INFINITY;
    for (double nm : {486.1327, 587.5618, 656.2725}) {  // blue F, yellow d, red C
        const double expected = (2 * std::asin(bk7.n(nm) * 0.5) - 60 * kDeg) / kDeg;
        const double measured = scanned_minimum_deviation(scene, nm).first;
        std::printf("N-BK7 prism at %.1f nm: minimum deviation %.4f deg (formula %.4f)\n", nm,
                    measured, expected);
        EXPECT_NEAR(measured, expected, 0.01);
        EXPECT_LT(measured, previous);  // longer wavelengths deviate less: red least
        previous = measured;
    }
    EXPECT_NEAR(bk7.n(486.1327), 1.52238, 2e-5);
    EXPECT_NEAR(bk7.n(656.2725), 1.51432, 2e-5);
}

}  // namespace
}  // namespace lenslab
