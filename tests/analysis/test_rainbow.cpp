// The primary rainbow: light entering a water drop, reflected once inside and leaving again,
// piles up at the minimum deviation D = 180 + 2i - 4r with cos^2 i = (n^2 - 1) / 3
// (Descartes' construction; Hecht, Optics, section 4.2 and problem 4.38). For water that is
// about 138 degrees, i.e. the bow 42 degrees from the antisolar point, red outside.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "analysis/trace/ray_tree.h"
#include "optics/glass.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

double descartes_minimum_deviation(double n) {
    const double i = std::acos(std::sqrt((n * n - 1.0) / 3.0));
    const double r = std::asin(std::sin(i) / n);
    return (std::numbers::pi + 2 * i - 4 * r) * kDegPerRad;
}

// The deviation at which once-reflected light leaving the drop is densest, for a parallel
// beam (+z) over the whole drop, at one wavelength.
double brightest_deviation(const Scene& scene, double nm) {
    constexpr double bin = 0.1;
    std::vector<double> histogram(static_cast<size_t>(180 / bin), 0.0);
    const int rays = 20000;
    RayTreeOptions options;
    options.wavelength_nm = nm;
    options.min_weight = 1e-9;
    options.max_depth = 3;
    for (int k = 0; k < rays; ++k) {
        // Impact parameters uniform over the drop's cross-section (area-weighted).
        const double b = std::sqrt((k + 0.5) / rays);
        const RayTree tree = trace_ray_tree(scene, {{0, b, -5}, {0, 0, 1}}, options);
        for (const RayTreeNode& in : tree.root.children) {
            if (in.event != Event::Refract) continue;
            for (const RayTreeNode& bounce : in.children) {
                if (bounce.event != Event::Reflect) continue;
                for (const RayTreeNode& out : bounce.children) {
                    if (out.event != Event::Refract) continue;
                    const double deviation =
                        std::acos(std::clamp(out.direction.z, -1.0, 1.0)) * kDegPerRad;
                    histogram[std::min(histogram.size() - 1,
                                       static_cast<size_t>(deviation / bin))] += out.weight;
                }
            }
        }
    }
    const size_t peak = std::max_element(histogram.begin(), histogram.end()) - histogram.begin();
    return (peak + 0.5) * bin;
}

TEST(Rainbow, OnceReflectedLightPeaksAtDescartesAngleRedOutside) {
    const Scene drop = parse_scene(R"({"camera": {"position": [0, 0, -10], "look_at": [0, 0, 0]},
        "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
                     "material": {"transparency": 1, "glass": "water"}}]})");
    const IndexModel& water = *find_glass("water")->model;
    const double red = brightest_deviation(drop, 656.3);
    const double blue = brightest_deviation(drop, 486.1);
    std::printf(
        "rainbow: red (656 nm) at %.2f deg, Descartes %.2f; blue (486 nm) at %.2f deg, Descartes "
        "%.2f\n",
        red, descartes_minimum_deviation(water.n(656.3)), blue,
        descartes_minimum_deviation(water.n(486.1)));
    // The histogram's peak sits at the minimum deviation, a bin's width above it at most.
    EXPECT_NEAR(red, descartes_minimum_deviation(water.n(656.3)), 0.3);
    EXPECT_NEAR(blue, descartes_minimum_deviation(water.n(486.1)), 0.3);
    EXPECT_NEAR(red, 137.7, 1.0);  // the textbook 42.3 degree bow for red
    // Red is deviated least: it makes the outside of the bow.
    EXPECT_LT(red, blue - 0.5);  // C to F lines: about 0.9 degrees apart
}

}  // namespace
}  // namespace lenslab
