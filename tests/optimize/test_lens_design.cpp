// The design file reader (lens_design.h): every mistake is refused with one message naming
// its JSON path; the examples in examples/optimize read.

#include <gtest/gtest.h>

#include "optimize/design_evaluation.h"
#include "optimize/lens_design.h"
#include "optimize/optimize_design.h"
#include "optimize_test_design.h"

namespace lenslab {
namespace {

using test::design_of;
using test::sphere;

const std::vector<test::LensSpec> kDesignLenses = {
    {"A", 0.0, 4.0, 20.0, sphere(50), sphere(0)},
    {"B", 10.0, 2.0, 20.0, sphere(0), sphere(-80)},
};

// The message of the SceneError reading `edit` into the design gives.
std::string design_error(const nlohmann::json& edit) {
    try {
        lens_design_from_json(design_of(kDesignLenses, edit), "");
    } catch (const SceneError& e) {
        return e.what();
    }
    return "(no error)";
}

// lenslab tolerance's designs need no variables or operands; lenslab optimize refuses a
// design without operands.
TEST(LensDesign, WithoutOperandsItReadsButIsNotOptimised) {
    nlohmann::json root = design_of(kDesignLenses, nlohmann::json::object());
    root.erase("operands");
    root.erase("variables");
    const LensDesign d = lens_design_from_json(root, "");
    EXPECT_TRUE(d.operands.empty() && d.variables.empty());
    try {
        optimize_design(d);
        ADD_FAILURE() << "optimised without operands";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "operands: missing (required: the merit function lenslab optimize minimises)");
    }
}

TEST(LensDesign, MistakesNameTheirJsonPath) {
    EXPECT_EQ(design_error({{"stops", 1}}), "stops: unknown key (did you mean 'stop'?)");
    EXPECT_NE(design_error({{"stop", 5}}).find("stop: "), std::string::npos);
    EXPECT_EQ(design_error({{"fields", {0, 95}}}),
              "fields[1]: not a field angle (between -90 and 90 degrees)");
    EXPECT_EQ(design_error({{"weights", {1, 2}}}),
              "weights: one weight per wavelength: 1 wavelengths, 2 weights");
    EXPECT_EQ(design_error({{"f_number", 4}}), "f_number: give epd or f_number, not both");
    EXPECT_EQ(design_error(
                  {{"variables", {{{"type", "curvature"}, {"lens", "Z"}, {"surface", "front"}}}}}),
              "variables[0].lens: no prescription lens named 'Z' in the system (lenses: A, B)");
    EXPECT_EQ(design_error({{"variables", {{{"type", "curvature"}, {"lens", "A"}}}}}),
              "variables[0].surface: missing (required)");
    EXPECT_EQ(design_error({{"tolerances", {{"criterion", "mtf"}}}}),
              "tolerances.frequency: the mtf criterion needs a frequency > 0 (cycles per unit "
              "length)");
    EXPECT_EQ(design_error({{"stop", 1}, {"stop_in_air", {{"lens", "A"}, {"distance", 2}}}}),
              "stop_in_air: give stop or stop_in_air, not both");
    // Farther than the next lens: the design's key says where.
    nlohmann::json inside =
        design_of(kDesignLenses, {{"stop_in_air", {{"lens", "A"}, {"distance", 7}}}});
    inside.erase("stop");
    try {
        (void)DesignModel(lens_design_from_json(inside, ""));
        ADD_FAILURE() << "a stop inside lens B was taken";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.path(), "stop_in_air.distance") << e.what();
    }
    nlohmann::json air =
        design_of(kDesignLenses, {{"stop_in_air", {{"lens", "Q"}, {"distance", 2}}}});
    air.erase("stop");
    try {
        lens_design_from_json(air, "");
        ADD_FAILURE() << "an unknown lens was taken";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "stop_in_air.lens: no prescription lens named 'Q' in the system (lenses: A, B)");
    }
    EXPECT_EQ(design_error({{"variables", {{{"type", "bend"}, {"lens", "A"}}}}}),
              "variables[0].type: unknown type 'bend' (known: curvature, conic, aspheric, "
              "thickness, air_gap, image_distance, n_d, V_d, decenter_x, decenter_y, tilt_x, "
              "tilt_y, delta_n_d, delta_V_d)");
    EXPECT_EQ(design_error({{"variables", {{{"type", "air_gap"}, {"lens", "B"}}}}}),
              "variables[0].lens: no lens behind 'B', so no air gap after it (the "
              "image_distance variable moves the image plane)");
    EXPECT_EQ(design_error({{"variables", {{{"type", "image_distance"}}}}}),
              "variables[0]: an image_distance variable needs a starting image_distance (a "
              "number, not the paraxial focus)");
    EXPECT_EQ(design_error(
                  {{"variables", {{{"type", "aspheric"}, {"lens", "A"}, {"surface", "front"}}}}}),
              "variables[0].surface: 'A' front is a sphere surface: aspheric coefficients need "
              "an asphere surface");
    EXPECT_EQ(design_error({{"variables",
                             {{{"type", "thickness"}, {"lens", "A"}},
                              {{"type", "thickness"}, {"lens", "A"}}}}}),
              "variables[1]: the same variable as variables[0] (thickness A)");
    EXPECT_EQ(design_error({{"operands", {{{"type", "efl"}}}}}),
              "operands[0].target: missing (required)");
    EXPECT_EQ(design_error(
                  {{"operands", {{{"type", "min_edge_thickness"}, {"lens", "A"}, {"target", 1}}}}}),
              "operands[0].target: a min_edge_thickness operand takes no target (it takes lens, "
              "limit, weight)");
    EXPECT_EQ(design_error({{"operands", {{{"type", "efl"}, {"target", 50}, {"weight", -1}}}}}),
              "operands[0].weight: must be >= 0, got -1");
    EXPECT_EQ(design_error({{"operands", nlohmann::json::array()}}),
              "operands: must be a non-empty array of operands");
    EXPECT_EQ(design_error({{"system", 3}}), "system: must be a scene file name or a scene object");
    EXPECT_EQ(design_error({{"glass_choices", {{{"lens", "A"}, {"glasses", {"N-BK7"}}}}}}),
              "glass_choices[0].lens: the lens 'A' needs its material written inline with a "
              "\"glass\" to choose among glasses");
}

TEST(LensDesign, UnknownGlassOfAChoiceIsNamed) {
    std::vector<test::LensSpec> lenses = kDesignLenses;
    lenses[0].material = test::glass("N-BK7");
    try {
        lens_design_from_json(
            design_of(lenses,
                      {{"glass_choices", {{{"lens", "A"}, {"glasses", {"N-BK7", "NBK7"}}}}}}),
            "");
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.path(), "glass_choices[0].glasses[1]");
        EXPECT_NE(e.reason().find("NBK7"), std::string::npos) << e.reason();
    }
}

TEST(LensDesign, SceneErrorsNameTheirPlaceInTheSystem) {
    nlohmann::json d = design_of(kDesignLenses);
    d["system"]["objects"][0]["thickness"] = -1;
    try {
        lens_design_from_json(d, "");
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.path(), "system.objects[0].thickness");
    }
}

TEST(LensDesign, TheExampleReads) {
    const LensDesign d = load_lens_design(std::string(LENSLAB_SOURCE_DIR) +
                                          "/examples/optimize/triplet.design.json");
    EXPECT_EQ(d.stop, 2);
    EXPECT_EQ(d.fields, (std::vector<double>{0, 14, 20}));
    EXPECT_EQ(d.variables.size(), 12u);
    EXPECT_EQ(d.primary_wavelength(), 587.5618);
}

}  // namespace
}  // namespace lenslab
