// The optimiser's variables (design_variable.h) written back into the scene: a curvature
// becomes the radius 1/c (a flat face bends into a sphere, a sphere of c = 0 goes flat); a
// thickness keeps the lens's front vertex and moves the lenses behind; an air gap moves
// every lens behind it and nothing in front. Checked on the optical system the scene reader
// builds from the written JSON, so the positions are the ones the bench sees.

#include <gtest/gtest.h>

#include "analysis/system/optical_system.h"
#include "optimize/design_evaluation.h"
#include "optimize_test_design.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

using test::design_of;
using test::sphere;

const std::vector<test::LensSpec> kVariableLenses = {
    {"A", 0.0, 4.0, 20.0, sphere(50), sphere(0)},
    {"B", 10.0, 2.0, 20.0, sphere(0), sphere(0)},
    {"C", 20.0, 3.0, 20.0, sphere(0), sphere(-60)},
};

LensDesign variable_design(const nlohmann::json& variables) {
    return lens_design_from_json(design_of(kVariableLenses, {{"variables", variables}}), "");
}

OpticalSystem variable_system(const DesignState& state) {
    return build_optical_system(
        scene_from_json(nlohmann::json(state.scene), "", {.require_camera = false}));
}

TEST(DesignVariable, CurvatureIsTheReciprocalRadius) {
    const LensDesign d =
        variable_design({{{"type", "curvature"}, {"lens", "A"}, {"surface", "front"}},
                         {{"type", "curvature"}, {"lens", "B"}, {"surface", "back"}}});
    const DesignModel model(d);
    const std::vector<double> start = model.start();
    EXPECT_DOUBLE_EQ(start[0], 1.0 / 50.0);
    EXPECT_EQ(start[1], 0.0);  // flat
    const DesignState bent = model.state_at({0.04, -0.01});
    EXPECT_DOUBLE_EQ(bent.scene["objects"][0]["front"]["radius"].get<double>(), 25.0);
    EXPECT_EQ(bent.scene["objects"][1]["back"]["shape"], "sphere");
    EXPECT_DOUBLE_EQ(bent.scene["objects"][1]["back"]["radius"].get<double>(), -100.0);
    const OpticalSystem system = variable_system(bent);
    EXPECT_NEAR(system.surfaces[0].curvature, 0.04, 1e-12);
    EXPECT_NEAR(system.surfaces[3].curvature, -0.01, 1e-12);
    const DesignState flat = model.state_at({0.0, 0.0});
    EXPECT_EQ(flat.scene["objects"][0]["front"]["shape"], "flat");
}

TEST(DesignVariable, AirGapMovesEveryLensBehind) {
    const LensDesign d = variable_design({{{"type", "air_gap"}, {"lens", "A"}}});
    const DesignModel model(d);
    EXPECT_NEAR(model.start()[0], 6.0, 1e-12);  // A's back vertex at 4, B's front at 10
    const OpticalSystem system = variable_system(model.state_at({8.5}));
    // A stays; B and C move by 2.5.
    EXPECT_NEAR(system.surfaces[0].z, 0.0, 1e-12);
    EXPECT_NEAR(system.surfaces[1].z, 4.0, 1e-12);
    EXPECT_NEAR(system.surfaces[2].z, 12.5, 1e-12);
    EXPECT_NEAR(system.surfaces[3].z, 14.5, 1e-12);
    EXPECT_NEAR(system.surfaces[4].z, 22.5, 1e-12);
    EXPECT_NEAR(system.surfaces[5].z, 25.5, 1e-12);
}

TEST(DesignVariable, ThicknessKeepsTheFrontVertex) {
    const LensDesign d = variable_design({{{"type", "thickness"}, {"lens", "B"}}});
    const DesignModel model(d);
    EXPECT_NEAR(model.start()[0], 2.0, 1e-12);
    const OpticalSystem system = variable_system(model.state_at({3.0}));
    EXPECT_NEAR(system.surfaces[2].z, 10.0, 1e-12);
    EXPECT_NEAR(system.surfaces[3].z, 13.0, 1e-12);
    EXPECT_NEAR(system.surfaces[4].z, 21.0, 1e-12);  // C moved by the extra 1
}

TEST(DesignVariable, ConicAndAsphericWriteTheirKeys) {
    std::vector<test::LensSpec> lenses = kVariableLenses;
    lenses[0].back = R"({"shape": "asphere", "radius": -80, "coefficients": [1e-6]})";
    const LensDesign d = lens_design_from_json(
        design_of(lenses,
                  {{"variables",
                    {{{"type", "conic"}, {"lens", "A"}, {"surface", "front"}},
                     {{"type", "aspheric"}, {"lens", "A"}, {"surface", "back"}, {"order", 6}}}}}),
        "");
    const DesignModel model(d);
    EXPECT_EQ(model.start(), (std::vector<double>{0.0, 0.0}));
    const DesignState s = model.state_at({-1.0, 2e-9});
    EXPECT_EQ(s.scene["objects"][0]["front"]["shape"], "conic");
    EXPECT_EQ(s.scene["objects"][0]["front"]["k"], -1.0);
    EXPECT_EQ(s.scene["objects"][0]["back"]["coefficients"], nlohmann::ordered_json({1e-6, 2e-9}));
}

}  // namespace
}  // namespace lenslab
