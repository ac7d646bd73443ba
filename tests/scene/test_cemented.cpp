// Cemented elements: two glasses sharing a surface refract and reflect by the ratio of their
// indices, as a lens group's cemented elements and two lens objects that touch both do.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "analysis/trace/ray_tree.h"
#include "optics/fresnel.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

// Crown (n = 1.5) cemented to flint (n = 1.7): a lens group of two elements, front vertex at
// the origin, shared surface R = -40 at z = 5, back R = -100 at z = 7.
std::string doublet(double n1, double n2,
                    const std::string& shared = R"({"shape": "sphere", "radius": -40})") {
    return R"({
      "camera": {"position": [0, 0, -100], "look_at": [0, 0, 0]},
      "materials": {"crown": {"transparency": 1, "ior": )" +
           std::to_string(n1) + R"(},
                    "flint": {"transparency": 1, "ior": )" +
           std::to_string(n2) + R"(}},
      "objects": [{"type": "lens_group", "name": "doublet", "vertex": [0, 0, 0], "axis": [0, 0, 1],
        "diameter": 20, "elements": [
          {"front": {"shape": "sphere", "radius": 50}, "thickness": 5, "material": "crown"},
          {"front": )" +
           shared + R"(, "thickness": 2, "material": "flint",
           "back": {"shape": "sphere", "radius": -100}}]}]
    })";
}

const RayTreeNode* child(const RayTreeNode& node, Event e) {
    for (const RayTreeNode& c : node.children) {
        if (c.event == e) return &c;
    }
    return nullptr;
}

double normal_reflectance(double n1, double n2) { return std::pow((n1 - n2) / (n1 + n2), 2); }

TEST(Cemented, LensGroupPlacesElementsFrontToBack) {
    const Scene scene = parse_scene(doublet(1.5, 1.7));
    ASSERT_EQ(scene.objects.size(), 2u);
    EXPECT_EQ(scene.objects[0].name, "doublet element 1");
    EXPECT_EQ(scene.objects[1].name, "doublet element 2");
    EXPECT_EQ(scene.objects[0].source, 0);  // both from the file's objects[0]
    EXPECT_EQ(scene.objects[1].source, 0);
    const RayTree tree = trace_ray_tree(scene, {{0, 0, -10}, {0, 0, 1}}, {});
    const RayTreeNode* in = child(tree.root, Event::Refract);
    ASSERT_NE(in, nullptr);
    EXPECT_NEAR(in->to->z, 0.0, 1e-12);
    const RayTreeNode* across = child(*in, Event::Refract);
    ASSERT_NE(across, nullptr);
    EXPECT_NEAR(across->to->z, 5.0, 1e-12);
    const RayTreeNode* out = child(*across, Event::Refract);
    ASSERT_NE(out, nullptr);
    EXPECT_NEAR(out->to->z, 7.0, 1e-12);
}

// At normal incidence R = ((n1 - n2) / (n1 + n2))^2 (Hecht, Optics, 5th ed., eq. 4.47) at
// each of the three surfaces; the shared one reflects (0.2 / 3.2)^2 = 0.0039, not the
// 0.04 + 0.067 two glass-air surfaces would.
TEST(Cemented, AxialRayLosesTheFresnelShareOfEachInterface) {
    const Scene scene = parse_scene(doublet(1.5, 1.7));
    const RayTree tree = trace_ray_tree(scene, {{0, 0, -10}, {0, 0, 1}}, {16, 1e-12});
    const RayTreeNode* in = child(tree.root, Event::Refract);
    ASSERT_NE(in, nullptr);
    const RayTreeNode* across = child(*in, Event::Refract);
    const RayTreeNode* back = child(*in, Event::Reflect);
    ASSERT_NE(across, nullptr);
    ASSERT_NE(back, nullptr);
    const double t_in = 1 - normal_reflectance(1.0, 1.5);
    EXPECT_NEAR(back->weight, t_in * normal_reflectance(1.5, 1.7), 1e-12);
    EXPECT_NEAR(normal_reflectance(1.5, 1.7), 0.00390625, 1e-15);
    const RayTreeNode* out = child(*across, Event::Refract);
    ASSERT_NE(out, nullptr);
    EXPECT_NEAR(out->weight,
                t_in * (1 - normal_reflectance(1.5, 1.7)) * (1 - normal_reflectance(1.7, 1.0)),
                1e-12);
}

// Snell's law across the shared surface: n1 |d1 x N| = n2 |d2 x N| (Hecht eq. 4.4), with the
// ray bent towards the normal going into the denser flint.
TEST(Cemented, ObliqueRayObeysSnellAcrossTheSharedSurface) {
    const Scene scene = parse_scene(doublet(1.5, 1.7));
    for (double h : {2.0, 5.0, 8.0}) {
        const RayTree tree = trace_ray_tree(scene, {{0, h, -10}, {0, 0, 1}}, {});
        const RayTreeNode* in = child(tree.root, Event::Refract);
        ASSERT_NE(in, nullptr);
        const RayTreeNode* across = child(*in, Event::Refract);
        ASSERT_NE(across, nullptr);
        // The shared surface is a sphere R = -40 with its vertex at z = 5: centre (0, 0, -35).
        const Vec3 p = *across->to;  // where the ray crossed the cement
        const Vec3 n = normalize(p - Vec3{0, 0, -35});
        EXPECT_NEAR(length(p - Vec3{0, 0, -35}), 40.0, 1e-9);
        const double sin_1 = length(cross(in->direction, n));
        const double sin_2 = length(cross(across->direction, n));
        EXPECT_GT(sin_1, 1e-3);
        EXPECT_NEAR(1.5 * sin_1, 1.7 * sin_2, 1e-12) << "h = " << h;
    }
}

// Two elements of the same glass cemented are one piece of glass: no reflection at the
// shared surface (R = 0 for equal indices) and the same path as a single lens.
TEST(Cemented, IndexMatchedElementsActAsOneLens) {
    const Scene split = parse_scene(doublet(1.6, 1.6));
    const Scene whole = parse_scene(R"({
      "camera": {"position": [0, 0, -100], "look_at": [0, 0, 0]},
      "objects": [{"type": "lens", "center": [0, 0, 3.5], "axis": [0, 0, 1], "thickness": 7,
        "diameter": 20, "front": {"shape": "sphere", "radius": 50},
        "back": {"shape": "sphere", "radius": -100},
        "material": {"transparency": 1, "ior": 1.6}}]
    })");
    for (double h : {1.0, 4.0, 9.0}) {
        const Ray ray{{0, h, -10}, {0, 0, 1}};
        const RayTree a = trace_ray_tree(split, ray, {16, 1e-12});
        const RayTree b = trace_ray_tree(whole, ray, {16, 1e-12});
        const RayTreeNode* a_in = child(a.root, Event::Refract);
        ASSERT_NE(a_in, nullptr);
        EXPECT_EQ(child(*a_in, Event::Reflect), nullptr);  // nothing reflected at the cement
        const RayTreeNode* a_out = child(*child(*a_in, Event::Refract), Event::Refract);
        const RayTreeNode* b_out = child(*child(b.root, Event::Refract), Event::Refract);
        ASSERT_NE(a_out, nullptr);
        ASSERT_NE(b_out, nullptr);
        EXPECT_NEAR(length(a_out->direction - b_out->direction), 0.0, 1e-12);
        EXPECT_NEAR(a_out->weight, b_out->weight, 1e-12);
        // The split lens has one more surface for weak inner reflections to end on, so the
        // depth limit cuts off slightly more power there (1e-8, not a loss).
        EXPECT_NEAR(a.escaped, b.escaped, 1e-8);
    }
}

// Two lens objects placed by hand so that they touch are cemented just like a lens group's
// elements; pulled 0.5 apart, an air gap separates them again.
TEST(Cemented, TouchingLensObjectsShareTheirSurface) {
    auto two_lenses = [](double gap) {
        return parse_scene(R"({
          "camera": {"position": [0, 0, -100], "look_at": [0, 0, 0]},
          "objects": [
            {"type": "lens", "center": [0, 0, 2.5], "axis": [0, 0, 1], "thickness": 5, "diameter": 20,
             "front": {"shape": "sphere", "radius": 50}, "back": {"shape": "flat"},
             "material": {"transparency": 1, "ior": 1.5}},
            {"type": "lens", "center": [0, 0, )" +
                           std::to_string(6 + gap) + R"(], "axis": [0, 0, 1],
             "thickness": 2, "diameter": 20, "front": {"shape": "flat"}, "back": {"shape": "flat"},
             "material": {"transparency": 1, "ior": 1.7}}]
        })");
    };
    const Scene touching = two_lenses(0);
    const Scene apart = two_lenses(0.5);
    EXPECT_EQ(touching.medium_beyond(0, {0, 0, 5}, {0, 0, 1}), &touching.material_of(1));
    EXPECT_EQ(touching.medium_beyond(1, {0, 0, 5}, {0, 0, -1}), &touching.material_of(0));
    EXPECT_EQ(touching.medium_beyond(1, {0, 0, 7}, {0, 0, 1}), nullptr);
    EXPECT_EQ(apart.medium_beyond(0, {0, 0, 5}, {0, 0, 1}), nullptr);

    const RayTree tree = trace_ray_tree(touching, {{0, 0, -10}, {0, 0, 1}}, {16, 1e-12});
    const RayTreeNode* in = child(tree.root, Event::Refract);
    ASSERT_NE(in, nullptr);
    const RayTreeNode* back = child(*in, Event::Reflect);
    ASSERT_NE(back, nullptr);
    EXPECT_NEAR(back->weight, (1 - 0.04) * normal_reflectance(1.5, 1.7), 1e-12);
}

// A ray inside the denser flint meeting the crown beyond the critical angle asin(1.5 / 1.7)
// = 61.9 degrees is totally reflected at the cement, which a glass-air surface would do
// beyond 36.0 degrees already.
TEST(Cemented, TotalInternalReflectionUsesTheIndexRatio) {
    const Scene scene = parse_scene(doublet(1.5, 1.7, R"({"shape": "flat"})"));
    const Vec3 origin{0, 0, 6};  // inside the flint
    auto event_at = [&](double degrees) {
        const double a = degrees * M_PI / 180;
        const RayTree tree =
            trace_ray_tree(scene, {origin, {0, std::sin(a), -std::cos(a)}}, {1, 1e-12});
        return tree.root.children.empty() ? Event::Escape : tree.root.children.front().event;
    };
    EXPECT_EQ(event_at(50), Event::Reflect);  // partial: reflected and refracted branches
    EXPECT_EQ(event_at(65), Event::Tir);
}

// Where a ray parallel to the axis at height 1 crosses the axis after the lens, at a
// wavelength: the paraxial focus at that wavelength.
double axial_focus(const Scene& scene, double lambda_nm) {
    RayTreeOptions options;
    options.wavelength_nm = lambda_nm;
    const RayTree tree = trace_ray_tree(scene, {{0, 1, -10}, {0, 0, 1}}, options);
    const RayTreeNode* node = &tree.root;
    while (const RayTreeNode* next = child(*node, Event::Refract)) node = next;
    return node->to->z - node->to->y * node->direction.z / node->direction.y;
}

// A thin lens's focal length changes between the F and C lines by f / V_d (Hecht, Optics,
// 5th ed., section 6.3.2): 1.6 mm for an N-BK7 lens of 100 mm (V_d = 64.17, SCHOTT data
// sheet). The cemented N-BK7 + F2 doublet of the scene-format document, designed by the
// achromat condition, brings the two lines together.
TEST(Cemented, AchromaticDoubletFocusesTheFAndCLinesTogether) {
    const std::string materials = R"("materials": {"crown": {"transparency": 1, "glass": "N-BK7"},
                                      "flint": {"transparency": 1, "glass": "F2"}},)";
    const Scene singlet =
        parse_scene(R"({"camera": {"position": [30, 0, 50], "look_at": [0, 0, 50]},)" + materials +
                    R"("objects": [{"type": "lens", "center": [0, 0, 2.5],
        "axis": [0, 0, 1], "thickness": 5, "diameter": 25, "material": "crown",
        "front": {"shape": "sphere", "radius": 102.4}, "back": {"shape": "sphere", "radius": -102.4}}]})");
    const Scene doublet =
        parse_scene(R"({"camera": {"position": [30, 0, 50], "look_at": [0, 0, 50]},)" + materials +
                    R"("objects": [{"type": "lens_group", "vertex": [0, 0, 0],
        "axis": [0, 0, 1], "diameter": 25, "elements": [
        {"front": {"shape": "sphere", "radius": 44.8}, "thickness": 6, "material": "crown"},
        {"front": {"shape": "sphere", "radius": -44.8}, "thickness": 2.5, "material": "flint",
         "back": {"shape": "sphere", "radius": -818}}]}]})");
    const double singlet_shift = axial_focus(singlet, 656.27) - axial_focus(singlet, 486.13);
    const double doublet_shift = axial_focus(doublet, 656.27) - axial_focus(doublet, 486.13);
    // Lensmaker's equation for the singlet at the d line (n_d = 1.5168): f = 1 / ((n - 1)
    // (2 / R - (n - 1) t / (n R^2))).
    const double n = 1.5168, r = 102.4, t = 5;
    const double f = 1.0 / ((n - 1) * (2 / r - (n - 1) * t / (n * r * r)));
    EXPECT_NEAR(singlet_shift, f / 64.17, 0.03 * f / 64.17);
    EXPECT_LT(std::abs(doublet_shift), 0.1 * singlet_shift);
}

}  // namespace
}  // namespace lenslab

namespace lenslab {
namespace {

// The chain of refracted branches from the camera ray: each surface the ray crosses (nodes
// of `tree`, which must outlive them).
std::vector<const RayTreeNode*> refracted_path(const RayTree& tree) {
    std::vector<const RayTreeNode*> path;
    for (const RayTreeNode* n = child(tree.root, Event::Refract); n; n = child(*n, Event::Refract))
        path.push_back(n);
    return path;
}

TEST(CementedGrin, AGradientIndexNeighbourRefractsWithItsOwnIndex) {
    // The flint as a uniform formula n = 1.7 (its plain ior left at the default 1.5): the
    // shared surface must refract by 1.5 / 1.7 as with plain glass, whichever of the two
    // copies of that surface a ray meets first.
    std::string grin = doublet(1.5, 1.7);
    const std::string plain_flint = R"("flint": {"transparency": 1, "ior": 1.700000})";
    const size_t at = grin.find(plain_flint);
    ASSERT_NE(at, std::string::npos);
    grin.replace(
        at, plain_flint.size(),
        R"("flint": {"transparency": 1, "grin": {"profile": "formula", "formula": "1.7"}})");
    const Scene graded = parse_scene(grin), plain = parse_scene(doublet(1.5, 1.7));
    for (double h : {1.0, 4.0, 9.0}) {
        const Ray ray{{0, h, -10}, {0, 0, 1}};
        const RayTree tree_a = trace_ray_tree(graded, ray, {}),
                      tree_b = trace_ray_tree(plain, ray, {});
        const std::vector<const RayTreeNode*> a = refracted_path(tree_a),
                                              b = refracted_path(tree_b);
        ASSERT_EQ(a.size(), 3u) << h;
        ASSERT_EQ(b.size(), 3u) << h;
        EXPECT_NEAR(length(a.back()->direction - b.back()->direction), 0.0, 1e-9) << h;
        EXPECT_NEAR(length(*a.back()->to - *b.back()->to), 0.0, 1e-7) << h;
    }
}

TEST(CementedGrin, TheSchematicEyeFocusesOnItsRetina) {
    // scenes/grin_eye.json, the Liou-Brennan eye: its paraxial ray equation, integrated for
    // the published profile, puts the focus 16.2388 mm behind the crystalline lens, 23.9689
    // mm behind the cornea: on the retina (23.96), as the model was designed (emmetropic).
    const Scene eye = load_scene_file(LENSLAB_SOURCE_DIR "/scenes/grin_eye.json");
    const auto crossing = [&](double h) {
        const RayTree tree = trace_ray_tree(eye, {{0, h, -5}, {0, 0, 1}}, {});
        const std::vector<const RayTreeNode*> path = refracted_path(tree);
        EXPECT_EQ(path.size(), 5u) << h;  // cornea, aqueous, lens, vitreous, retina
        const RayTreeNode& vitreous = *path[path.size() - 2];
        const Vec3 p = *vitreous.to, d = vitreous.direction;
        return std::pair{p.z - p.y / d.y * d.z, path.back()->to->y};
    };
    EXPECT_NEAR(crossing(0.01).first, 23.9689, 0.002);
    // A 1 mm pupil's rim ray lands within 2 um of the fovea's centre.
    EXPECT_NEAR(crossing(0.5).second, 0.0, 0.002);
}

}  // namespace
}  // namespace lenslab
