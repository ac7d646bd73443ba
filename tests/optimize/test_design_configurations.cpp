// Multi-configuration designs (optimize/design_configurations.h) on the two-group zoom of
// examples/optimize/zoom.design.json: each configuration evaluates as the same design written
// out by hand for it alone (its air gap moved in the scene, its fields, the shared operands
// and its own), the reader's refusals, and the optimised zoom meeting its focal lengths.

#include <gtest/gtest.h>

#include <fstream>

#include "optimize/design_configurations.h"
#include "optimize/design_evaluation.h"
#include "optimize/optimize_design.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

const std::string kZoomFolder = LENSLAB_SOURCE_DIR "/examples/optimize";

nlohmann::json zoom_json() { return read_scene_json_file(kZoomFolder + "/zoom.design.json"); }

// Configuration `k` of the zoom as a design of its own: the rear group moved by hand so the
// air gap after L2 is the configuration's.
nlohmann::json zoom_configuration_by_hand(size_t k) {
    nlohmann::json root = zoom_json();
    const nlohmann::json c = root["configurations"][k];
    nlohmann::json scene = read_scene_json_file(kZoomFolder + "/zoom_start.json");
    nlohmann::json& objects = scene["objects"];
    const double l2_back =
        objects[1]["center"][2].get<double>() + 0.5 * objects[1]["thickness"].get<double>();
    const double l3_front =
        objects[2]["center"][2].get<double>() - 0.5 * objects[2]["thickness"].get<double>();
    const double shift = c["air_gaps"]["L2"].get<double>() - (l3_front - l2_back);
    for (size_t i = 2; i < objects.size(); ++i) {
        objects[i]["center"][2] = objects[i]["center"][2].get<double>() + shift;
    }
    root["system"] = scene;
    root["fields"] = c["fields"];
    for (const nlohmann::json& op : c["operands"]) root["operands"].push_back(op);
    root.erase("configurations");
    root.erase("variables");
    return root;
}

TEST(DesignConfigurations, EachConfigurationEvaluatesAsItsOwnDesign) {
    const LensDesign zoom = load_lens_design(kZoomFolder + "/zoom.design.json");
    ASSERT_EQ(zoom.configurations.size(), 3u);
    const DesignModel model(zoom);
    const std::optional<DesignEvaluation> all = model.evaluate(model.start());
    ASSERT_TRUE(all);
    size_t next = 0;
    double merit = 0;
    for (size_t k = 0; k < 3; ++k) {
        const LensDesign alone = lens_design_from_json(zoom_configuration_by_hand(k), kZoomFolder);
        const DesignModel one(alone);
        const std::optional<DesignEvaluation> e = one.evaluate(one.start());
        ASSERT_TRUE(e);
        for (size_t i = 0; i < e->values.size(); ++i, ++next) {
            ASSERT_LT(next, all->values.size());
            EXPECT_NEAR(all->values[next], e->values[i], 1e-9 * std::abs(e->values[i]))
                << zoom.operands[next].path << " " << operand_label(zoom.operands[next]);
            EXPECT_EQ(zoom.operands[next].configuration, int(k));
        }
        EXPECT_NEAR(all->configuration_efl[k], e->efl, 1e-9 * e->efl);
        merit += e->merit;
    }
    EXPECT_EQ(next, all->values.size());
    EXPECT_NEAR(all->merit, merit, 1e-9 * merit);
    // The labels say the configuration.
    EXPECT_EQ(operand_label(zoom.operands[8]), "efl [wide]");  // after 3 spots, 5 edges
    EXPECT_EQ(variable_label(zoom.variables.back()), "air_gap L2 [tele]");
}

std::string zoom_error(const std::function<void(nlohmann::json&)>& edit) {
    nlohmann::json root = zoom_json();
    edit(root);
    try {
        lens_design_from_json(root, kZoomFolder);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(DesignConfigurations, MistakesNameTheirJsonPath) {
    EXPECT_EQ(zoom_error([](nlohmann::json& r) { r["variables"][10]["configuration"] = "zoom"; }),
              "variables[10].configuration: must name a configuration, or number it from 1 to 3");
    EXPECT_EQ(zoom_error([](nlohmann::json& r) { r["variables"][10].erase("configuration"); }),
              "variables[10]: configuration 'wide' sets this air gap: give the variable a "
              "configuration");
    EXPECT_EQ(zoom_error([](nlohmann::json& r) { r["configurations"][1]["name"] = "wide"; }),
              "configurations[1].name: another configuration is named 'wide'");
    EXPECT_EQ(zoom_error([](nlohmann::json& r) { r["configurations"][2]["name"] = "a/b"; }),
              "configurations[2].name: must be letters, digits, _ and -, got 'a/b'");
    EXPECT_EQ(zoom_error([](nlohmann::json& r) {
                  r["configurations"][0]["air_gaps"] = {{"L9", 3}};
              }),
              "configurations[0].air_gaps.L9: no prescription lens named 'L9' in the system "
              "(lenses: L1, L2, L3, L4, L5)");
    EXPECT_EQ(zoom_error([](nlohmann::json& r) {
                  r["configurations"] = nlohmann::json::array({r["configurations"][0]});
              }),
              "configurations: must be an array of at least two configurations (one is the "
              "design)");
    EXPECT_EQ(zoom_error([](nlohmann::json& r) { r["configurations"][0]["image_distance"] = 50; }),
              "configurations[0].image_distance: the design's image plane is the paraxial focus: "
              "give the design an image_distance first");
    // A shared variable would override what a configuration sets, or a configuration's own.
    EXPECT_EQ(zoom_error([](nlohmann::json& r) {
                  r["image_distance"] = 60;
                  r["configurations"][2]["image_distance"] = 70;
                  r["variables"].push_back({{"type", "image_distance"}});
              }),
              "variables[13]: configuration 'tele' sets this image distance: give the variable "
              "a configuration");
    EXPECT_EQ(zoom_error([](nlohmann::json& r) {
                  r["variables"].push_back({{"type", "curvature"},
                                            {"lens", "L1"},
                                            {"surface", "front"},
                                            {"configuration", "tele"}});
              }),
              "variables[13]: the same variable as variables[0] (curvature L1.front)");
    // Numbered from 1, as the reports number surfaces.
    EXPECT_EQ(zoom_error([](nlohmann::json& r) { r["variables"][10]["configuration"] = 1; }),
              "(no error)");
}

// The example: the three focal lengths met and every field's polychromatic RMS spot under
// 15 µm (measured 4.6 to 13.7 µm), the configurations' scenes written with their own gaps.
TEST(DesignConfigurations, TheZoomMeetsItsFocalLengths) {
    const LensDesign zoom = load_lens_design(kZoomFolder + "/zoom.design.json");
    const OptimizeResult r = optimize_design(zoom);
    ASSERT_EQ(r.after.configurations.size(), 3u);
    const double targets[] = {30, 40, 55};
    for (size_t k = 0; k < 3; ++k) EXPECT_NEAR(r.after.configurations[k].efl, targets[k], 0.01);
    for (const OperandRow& row : r.after.operands) {
        if (row.label.rfind("rms_spot", 0) == 0) {
            EXPECT_LT(row.value, 0.015) << row.label;
        }
    }
    ASSERT_EQ(r.configuration_scenes.size(), 2u);
    EXPECT_EQ(r.configuration_scenes[1].first, "tele");
    // The tele configuration's scene: its rear group nearer the front group than the wide's.
    EXPECT_LT(r.configuration_scenes[1].second["objects"][2]["center"][2].get<double>(),
              r.scene["objects"][2]["center"][2].get<double>());
}

}  // namespace
}  // namespace lenslab
