// Equation-defined objects render the same images as their analytic twins: a sphere written
// as the implicit equation x^2 + y^2 + z^2 - R^2 <= 0, and a biconvex spherical lens whose
// faces are typed sag formulas R - sqrt(R^2 - r^2). "The same" means: the per-pixel
// difference between the twins is far below the noise, measured as the difference between
// two renders of the analytic scene with different seeds.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "render/render_session.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

// A glass object in front of a two-coloured wall, lit by a small emitting sphere (soft
// shadows and glints: noise for the seed comparison).
Scene scene_with(const std::string& object, int seed) {
    return parse_scene(R"({
      "camera": {"position": [0, 0.3, 4], "look_at": [0, 0, 0], "fov": 30},
      "render": {"width": 96, "height": 72, "spp": 4, "max_depth": 8, "seed": )" +
                       std::to_string(seed) + R"(, "ambient": 0.1, "light_samples": 2},
      "materials": {
        "glass": {"color": 1, "transparency": 1, "ior": 1.5},
        "red": {"color": [0.8, 0.2, 0.1]}, "blue": {"color": [0.1, 0.3, 0.8]},
        "lamp": {"color": 0, "emission": {"color": 1, "intensity": 60}}
      },
      "objects": [
        {"type": "triangle", "vertices": [[-4, -3, -2], [4, -3, -2], [4, 0, -2]], "material": "blue"},
        {"type": "triangle", "vertices": [[-4, -3, -2], [4, 0, -2], [-4, 0, -2]], "material": "blue"},
        {"type": "triangle", "vertices": [[-4, 0, -2], [4, 0, -2], [4, 3, -2]], "material": "red"},
        {"type": "triangle", "vertices": [[-4, 0, -2], [4, 3, -2], [-4, 3, -2]], "material": "red"},
        {"type": "sphere", "center": [1.5, 2, 2], "radius": 0.3, "material": "lamp"},
        )" + object + R"(
      ]
    })");
}

struct Difference {
    double mean;     // mean absolute difference per channel
    double changed;  // fraction of pixels that differ by more than 1e-4 in some channel
};

Difference difference(const Film& a, const Film& b) {
    double sum = 0;
    int changed = 0;
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
            const auto& p = a.at(x, y);
            const auto& q = b.at(x, y);
            const double d[3] = {std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b)};
            sum += d[0] + d[1] + d[2];
            changed += std::max({d[0], d[1], d[2]}) > 1e-4;
        }
    }
    const double n = double(a.width()) * a.height();
    return {sum / (3.0 * n), changed / n};
}

Film render_twin(const Scene& scene) {
    RenderControl control;
    return render_scene(scene, control).film;
}

void expect_twins(const std::string& analytic, const std::string& equation) {
    const Film reference = render_twin(scene_with(analytic, 1));
    const Film twin = render_twin(scene_with(equation, 1));
    const Film reseeded = render_twin(scene_with(analytic, 2));
    const Difference twins = difference(reference, twin);
    const Difference noise = difference(reference, reseeded);
    std::printf(
        "analytic vs equation: mean %.3g, %.2g%% of pixels differ; seed 1 vs seed 2: "
        "mean %.3g, %.2g%% of pixels differ\n",
        twins.mean, 100 * twins.changed, noise.mean, 100 * noise.changed);
    EXPECT_GT(noise.mean, 1e-3);  // the comparison has noise to measure against
    // The twins' hits agree to about 1e-12, so nearly every pixel is the same to the last
    // bit. A few differ by noise: where a path ends on the (black, diffuse) lamp, a point
    // 1e-12 away can fall on the other side of direct_light's "inside the light" test and so
    // draw, or not, the random numbers of shadow rays that light nothing, which reshuffles
    // the pixel's later samples.
    EXPECT_LT(twins.mean, 0.25 * noise.mean);
    EXPECT_LT(twins.changed, 0.25 * noise.changed);
}

TEST(EquationTwins, ImplicitSphereRendersAsTheSphere) {
    expect_twins(R"({"type": "sphere", "center": [0, 0, 0], "radius": 0.8, "material": "glass"})",
                 R"({"type": "implicit", "formula": "x^2 + y^2 + z^2 - 0.64",
            "bounds": [[-0.9, -0.9, -0.9], [0.9, 0.9, 0.9]], "material": "glass"})");
}

TEST(EquationTwins, SagFormulaLensRendersAsTheSphericalLens) {
    const std::string frame = R"("type": "lens", "center": [0, 0, 0], "axis": [0.3, 0.2, 1],
        "thickness": 0.5, "diameter": 1.6, "material": "glass", )";
    expect_twins("{" + frame + R"("front": {"shape": "sphere", "radius": 1.5},
                         "back": {"shape": "sphere", "radius": -1.5}})",
                 "{" + frame + R"j("front": {"shape": "sag", "formula": "1.5 - sqrt(1.5^2 - r^2)"},
                          "back": {"shape": "sag", "formula": "-(1.5 - sqrt(1.5^2 - r^2))"}})j");
}

}  // namespace
}  // namespace lenslab
