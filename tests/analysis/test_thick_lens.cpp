// A paraxial ray through a thick biconvex lens crosses the axis at the back focal distance
// of the thick-lens equation (Hecht, Optics, 5th ed., eqs. 6.2 and 6.3):
//   1/f = (n - 1) [1/R1 - 1/R2 + (n - 1) d / (n R1 R2)],  BFD = f (1 - (n - 1) d / (n R1)).

#include <gtest/gtest.h>

#include "analysis/trace/ray_tree.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

Scene lens_scene(double r1, double r2, double thickness, double n) {
    const std::string text = R"({
      "camera": {"position": [0, 0, -200], "look_at": [0, 0, 0]},
      "objects": [{"type": "lens", "center": [0, 0, 0], "axis": [0, 0, 1],
                   "thickness": )" +
                             std::to_string(thickness) + R"(, "diameter": 25,
                   "front": {"shape": "sphere", "radius": )" +
                             std::to_string(r1) + R"(},
                   "back": {"shape": "sphere", "radius": )" +
                             std::to_string(r2) + R"(},
                   "material": {"transparency": 1, "ior": )" +
                             std::to_string(n) + R"(}}]
    })";
    return parse_scene(text);
}

// Follows the refracted branch through both faces and returns where the outgoing ray
// meets the axis (z coordinate).
double axis_crossing(const Scene& scene, double height) {
    const RayTree tree = trace_ray_tree(scene, {{0, height, -100}, {0, 0, 1}}, {});
    const RayTreeNode* node = &tree.root;
    for (int face = 0; face < 2; ++face) {
        const RayTreeNode* next = nullptr;
        for (const RayTreeNode& c : node->children) {
            if (c.event == Event::Refract) next = &c;
        }
        EXPECT_NE(next, nullptr);
        if (!next) return 0;
        node = next;
    }
    const Vec3 p = *node->to, d = node->direction;
    return p.z - p.y / d.y * d.z;
}

TEST(ThickLens, ParaxialRayFocusesAtTheBackFocalDistance) {
    const double r1 = 50, r2 = -50, d = 5, n = 1.5;
    const double power = (n - 1) * (1 / r1 - 1 / r2 + (n - 1) * d / (n * r1 * r2));
    const double f = 1 / power;                           // 50.847
    const double bfd = f * (1 - (n - 1) * d / (n * r1));  // 49.153 from the back vertex
    const Scene scene = lens_scene(r1, r2, d, n);
    const double measured = axis_crossing(scene, 0.05) - d / 2;  // back vertex at z = +d/2
    EXPECT_NEAR(measured, bfd, 1e-3 * bfd);
    EXPECT_NEAR(bfd, 49.1525, 1e-3);
}

TEST(ThickLens, MarginalRaysFocusShorterThanParaxial) {
    // Spherical aberration of a biconvex lens is undercorrected: rays far from the axis cross
    // it closer to the lens (Hecht section 6.3.1).
    const Scene scene = lens_scene(50, -50, 5, 1.5);
    EXPECT_LT(axis_crossing(scene, 10.0), axis_crossing(scene, 0.05) - 0.1);
}

TEST(ThickLens, PlanoConvexFocusMatchesLensmaker) {
    // Flat back: BFD = f - d / n with f = R1 / (n - 1) (Hecht eq. 6.3 with R2 -> infinity).
    const std::string text = R"({
      "camera": {"position": [0, 0, -200], "look_at": [0, 0, 0]},
      "objects": [{"type": "lens", "center": [0, 0, 0], "axis": [0, 0, 1],
                   "thickness": 4, "diameter": 25,
                   "front": {"shape": "sphere", "radius": 30}, "back": {"shape": "flat"},
                   "material": {"transparency": 1, "ior": 1.5}}]
    })";
    const double f = 30 / 0.5, bfd = f - 4 / 1.5;
    EXPECT_NEAR(axis_crossing(parse_scene(text), 0.05) - 2.0, bfd, 1e-3 * bfd);
}

}  // namespace
}  // namespace lenslab
