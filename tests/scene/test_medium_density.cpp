// A medium's `density`: read from a shape's medium and the atmosphere, its majorant
// estimated over the medium's box (or the user's, checked), and a density that is no
// density (negative, undefined, not a formula, a bound below it) refused with one message
// naming its JSON path.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>

#include "scene/scene_json.h"
#include "util/scene_error.h"

namespace lenslab {
namespace {

// A scene with a 2-unit box of smoke at the origin whose medium has `medium_keys`.
std::string density_box_scene(const std::string& medium_keys) {
    return R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
      "objects": [{"type": "box", "center": [0, 0, 0], "size": [2, 2, 2],
                   "medium": {"scattering": 0.5, )" +
           medium_keys + "}}]}";
}

TEST(MediumDensity, TheBoundIsTheGridsMaximumWithAMargin) {
    // f = 1 + x over x in [-1, 1]: the grid's corners include x = 1, f = 2.
    const Scene scene = parse_scene(density_box_scene(R"("density": "1 + x")"));
    const Medium& m = *scene.objects[0].medium;
    ASSERT_TRUE(m.is_heterogeneous());
    EXPECT_DOUBLE_EQ(m.density->bound(), 2 * MediumDensity::kSafety);
    EXPECT_DOUBLE_EQ(m.density->region().hi.x, 1.0);
    EXPECT_EQ(m.density->owner(), "objects[0].medium.density");
}

TEST(MediumDensity, TheUsersBoundIsKept) {
    const Scene scene = parse_scene(density_box_scene(R"("density": "1 + x", "density_max": 3)"));
    EXPECT_DOUBLE_EQ(scene.objects[0].medium->density->bound(), 3.0);
}

TEST(MediumDensity, NoDensityIsHomogeneous) {
    EXPECT_FALSE(parse_scene(density_box_scene(R"("g": 0)")).objects[0].medium->is_heterogeneous());
    EXPECT_FALSE(
        parse_scene(density_box_scene(R"("density": "")")).objects[0].medium->is_heterogeneous());
}

TEST(MediumDensity, TheAtmosphereIsBoundedOverTheScene) {
    const Scene scene = parse_scene(R"j({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
      "atmosphere": {"scattering": 0.1, "density": "exp(-y)"},
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
                   "material": {"color": 0.5}}]})j");
    ASSERT_TRUE(scene.atmosphere && scene.atmosphere->is_heterogeneous());
    const Aabb& region = scene.atmosphere->density->region();
    // The sphere and the camera, with a margin.
    EXPECT_LT(region.lo.y, -1.0);
    EXPECT_GT(region.hi.z, 5.0);
    EXPECT_GE(scene.atmosphere->density->bound(), std::exp(-region.lo.y));
}

// The one message a bad density gives: its path and its reason.
std::pair<std::string, std::string> density_refusal(const std::string& medium_keys) {
    try {
        parse_scene(density_box_scene(medium_keys));
    } catch (const SceneError& e) {
        return {e.path(), e.reason()};
    }
    return {"", "accepted"};
}

TEST(MediumDensity, RefusesANegativeDensity) {
    const auto [path, reason] = density_refusal(R"("density": "x")");
    EXPECT_EQ(path, "objects[0].medium.density");
    EXPECT_NE(reason.find("must be >= 0"), std::string::npos) << reason;
}

TEST(MediumDensity, RefusesAnUndefinedDensity) {
    const auto [path, reason] = density_refusal(R"j("density": "sqrt(x)")j");
    EXPECT_EQ(path, "objects[0].medium.density");
    EXPECT_NE(reason.find("undefined"), std::string::npos) << reason;
}

TEST(MediumDensity, RefusesTextThatIsNoFormula) {
    const auto [path, reason] = density_refusal(R"("density": "1 + * x")");
    EXPECT_EQ(path, "objects[0].medium.density");
    EXPECT_NE(reason.find("position"), std::string::npos) << reason;
    const auto [unknown_path, unknown] = density_refusal(R"("density": "q")");
    EXPECT_EQ(unknown_path, "objects[0].medium.density");
    EXPECT_NE(unknown.find("unknown variable 'q'"), std::string::npos) << unknown;
}

TEST(MediumDensity, RefusesABoundBelowTheDensity) {
    const auto [path, reason] = density_refusal(R"("density": "2 + x", "density_max": 2)");
    EXPECT_EQ(path, "objects[0].medium.density_max");
    EXPECT_NE(reason.find("reaches 3"), std::string::npos) << reason;
    EXPECT_EQ(density_refusal(R"("density_max": 2)").first, "objects[0].medium.density_max");
    EXPECT_EQ(density_refusal(R"("density": "1", "density_max": 0)").first,
              "objects[0].medium.density_max");
}

TEST(MediumDensity, TrackingClampsToTheBoundAndCounts) {
    // A spike between the grid's points (every 1/16 of the box): above the user's bound.
    const Scene scene = parse_scene(density_box_scene(
        R"j("density": "1 + 100 * (abs(x - 0.03) < 0.01)", "density_max": 1.5)j"));
    const MediumDensity& d = *scene.objects[0].medium->density;
    MediumDensity::Local f = d.local();
    EXPECT_DOUBLE_EQ(f({0.03, 0, 0}), 1.5);
    EXPECT_EQ(d.points_clamped(), 1u);
    EXPECT_DOUBLE_EQ(f({0.5, 0, 0}), 1.0);
    EXPECT_DOUBLE_EQ(f({5, 0, 0}), 0.0);  // outside the box
}

// A grid: two values along x, interpolated linearly between the box's faces, 0 outside it;
// its bound is its largest value, exactly.
TEST(MediumDensity, AGridInterpolatesItsValues) {
    const Scene scene = parse_scene(density_box_scene(
        R"("density": {"grid": [2, 1, 1], "box": [[0, 0, 0], [1, 1, 1]], "values": [1, 3]})"));
    const MediumDensity& d = *scene.objects[0].medium->density;
    EXPECT_DOUBLE_EQ(d.bound(), 3.0);
    MediumDensity::Local f = d.local();
    EXPECT_DOUBLE_EQ(f({0.25, 0.5, 0.5}), 1.5);
    EXPECT_DOUBLE_EQ(f({1, 1, 1}), 3.0);
    EXPECT_DOUBLE_EQ(f({-0.5, 0.5, 0.5}), 0.0);  // in the medium's box, not the grid's
    EXPECT_EQ(d.points_clamped(), 0u);
}

TEST(MediumDensity, RefusesABadGrid) {
    const std::string grid = R"("density": {"grid": [2, 1, 1], "box": [[0, 0, 0], [1, 1, 1]], )";
    EXPECT_EQ(density_refusal(grid + R"("values": [1, -2]})").first,
              "objects[0].medium.density.values[1]");
    EXPECT_EQ(density_refusal(grid + R"("values": [1]})").first,
              "objects[0].medium.density.values");
    EXPECT_EQ(density_refusal(grid + R"("values": [1, 2], "cells": 3})").first,
              "objects[0].medium.density.cells");
    EXPECT_EQ(density_refusal(R"("density": {"grid": [2, 0.5, 1], "box": [[0, 0, 0], [1, 1, 1]],
                                      "values": [1, 2]})")
                  .first,
              "objects[0].medium.density.grid[1]");
    EXPECT_EQ(density_refusal(R"("density": {"grid": [2, 1, 1], "box": [[0, 0, 0], [1, 0, 1]],
                                      "values": [1, 2]})")
                  .first,
              "objects[0].medium.density.box");
    const auto [path, reason] = density_refusal(grid + R"("values": [1, 4]}, "density_max": 3)");
    EXPECT_EQ(path, "objects[0].medium.density_max");
    EXPECT_NE(reason.find("reaches 4"), std::string::npos) << reason;
}

}  // namespace
}  // namespace lenslab
