// The editor's edits of a scene's objects and lights (scene/element_edits.h), without Qt: what
// each adds or removes, where it puts it, what it names it and what it refuses.

#include <gtest/gtest.h>

#include "scene/element_edits.h"
#include "scene/light_spec.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

using nlohmann::json;

json two_spheres_scene() {
    return json::parse(R"({
        "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
        "objects": [
            {"type": "sphere", "name": "ball", "center": [0, 2, 0], "radius": 1,
             "material": {"color": 0.5}},
            {"type": "sphere", "name": "sphere", "center": [3, 0, 0], "radius": 0.5,
             "material": {"color": 0.5}}],
        "lights": [{"type": "point", "position": [0, 5, 0], "power": 10}]})");
}

TEST(ElementEdits, NamesAreMadeUniqueAmongTheObjects) {
    const json scene = two_spheres_scene();
    EXPECT_EQ(unique_object_name(scene, "lens"), "lens");
    EXPECT_EQ(unique_object_name(scene, "sphere"), "sphere 2");
    json with_second = scene;
    with_second["objects"].push_back({{"name", "sphere 2"}});
    EXPECT_EQ(unique_object_name(with_second, "sphere"), "sphere 3");
    EXPECT_EQ(unique_object_name(json::object(), "sphere"), "sphere");
}

TEST(ElementEdits, ListsAndDeclarationsFollowTheType) {
    EXPECT_EQ(element_list("point"), "lights");
    EXPECT_EQ(element_list("spot"), "lights");
    EXPECT_EQ(element_list("sphere"), "objects");
    ASSERT_NE(element_spec("objects", "sphere"), nullptr);
    EXPECT_EQ(element_spec("objects", "sphere")->name, "sphere");
    EXPECT_EQ(element_spec("lights", "point"), find_light_spec("point"));
    EXPECT_EQ(element_spec("objects", "teapot"), nullptr);
}

TEST(ElementEdits, AnAddedElementIsMovedNamedAndSelected) {
    const json scene = two_spheres_scene();
    const json example = element_spec("objects", "sphere")->example;
    const ElementEdit edit =
        with_element(scene, "objects", placed_element(scene, "objects", example, {1, 2, 3}));
    EXPECT_EQ(edit.pointer, "/objects/2");
    const json& added = edit.scene["objects"][2];
    EXPECT_EQ(added["name"], "sphere 2");
    EXPECT_EQ(added["center"], json::array({1.0, 2.0, 3.0}));
    EXPECT_EQ(added["radius"], example["radius"]);
    EXPECT_EQ(scene["objects"].size(), 2u);  // the input is never changed

    // A scene without the list gets one.
    const ElementEdit light = with_element(json::object(), "lights", json{{"type", "point"}});
    EXPECT_EQ(light.pointer, "/lights/0");
    EXPECT_EQ(light.scene["lights"].size(), 1u);
}

TEST(ElementEdits, ADuplicateIsACopyBesideTheOriginal) {
    const json scene = two_spheres_scene();
    const auto edit = with_duplicate(scene, "/objects/0");
    ASSERT_TRUE(edit);
    EXPECT_EQ(edit->pointer, "/objects/2");
    const json& copy = edit->scene["objects"][2];
    EXPECT_EQ(copy["name"], "ball copy");
    EXPECT_EQ(copy["center"], json::array({0.5, 2.0, 0.0}));
    EXPECT_EQ(copy["radius"], 1);

    const auto light = with_duplicate(scene, "/lights/0");
    ASSERT_TRUE(light);
    EXPECT_EQ(light->pointer, "/lights/1");
    EXPECT_EQ(light->scene["lights"][1]["position"], json::array({0.5, 5.0, 0.0}));

    // Only objects and lights that exist.
    EXPECT_FALSE(with_duplicate(scene, "/camera"));
    EXPECT_FALSE(with_duplicate(scene, "/objects/7"));
    EXPECT_FALSE(with_duplicate(scene, "/objects/0/center"));
    EXPECT_FALSE(with_duplicate(scene, ""));
}

TEST(ElementEdits, DeleteRemovesTheElementItNames) {
    const json scene = two_spheres_scene();
    const auto edit = without_element(scene, "/objects/0");
    ASSERT_TRUE(edit);
    // The selection moves to the neighbour that took its place.
    EXPECT_EQ(edit->pointer, "/objects/0");
    ASSERT_EQ(edit->scene["objects"].size(), 1u);
    EXPECT_EQ(edit->scene["objects"][0]["name"], "sphere");
    // The last one removed: the one before it; the only one removed: nothing.
    EXPECT_EQ(without_element(scene, "/objects/1")->pointer, "/objects/0");
    EXPECT_EQ(without_element(edit->scene, "/objects/0")->pointer, "");

    json foggy = scene;
    foggy["atmosphere"] = json::object();
    const auto clear = without_element(foggy, "/atmosphere");
    ASSERT_TRUE(clear);
    EXPECT_FALSE(clear->scene.contains("atmosphere"));
    EXPECT_EQ(clear->pointer, "");

    EXPECT_FALSE(without_element(scene, "/atmosphere"));  // it has none
    EXPECT_FALSE(without_element(scene, "/render"));
    EXPECT_FALSE(without_element(scene, "/lights/1"));
    EXPECT_FALSE(without_element(scene, "/objects/x"));
}

TEST(ElementEdits, TheFloorLiesUnderTheLowestObjectFourTimesTheSceneWide) {
    const json scene = two_spheres_scene();
    const Scene built = scene_from_json(scene);
    // The objects span x from -1 to 3.5 (4.5, the widest extent), y from -0.5 to 3.
    const json floor = floor_under(built, scene);
    EXPECT_EQ(floor["type"], "box");
    EXPECT_EQ(floor["name"], "floor");
    const double side = 4 * 4.5, thickness = side / 100;
    EXPECT_DOUBLE_EQ(floor["size"][0].get<double>(), side);
    EXPECT_DOUBLE_EQ(floor["size"][1].get<double>(), thickness);
    EXPECT_DOUBLE_EQ(floor["center"][1].get<double>(), -0.5 - thickness / 2);
    EXPECT_DOUBLE_EQ(floor["center"][0].get<double>(), 1.25);
    // Read back, it is a valid object of the scene.
    json with_floor = with_element(scene, "objects", floor).scene;
    EXPECT_NO_THROW(scene_from_json(with_floor));
    EXPECT_EQ(floor_under(built, with_floor)["name"], "floor 2");

    const json empty = json::parse(R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]}})");
    const json alone = floor_under(scene_from_json(empty), empty);
    EXPECT_DOUBLE_EQ(alone["size"][0].get<double>(), 10.0);
    EXPECT_DOUBLE_EQ(alone["center"][1].get<double>(), -0.05);
}

TEST(ElementEdits, AnAtmosphereIsAddedOnce) {
    const json scene = two_spheres_scene();
    const json foggy = with_atmosphere(scene);
    ASSERT_TRUE(foggy.contains("atmosphere"));
    EXPECT_NO_THROW(scene_from_json(foggy));
    EXPECT_EQ(foggy["render"]["volume_neighbours"], kAtmosphereVolumeNeighbours);
    json chosen = scene;
    chosen["render"]["volume_neighbours"] = 4;
    EXPECT_EQ(with_atmosphere(chosen)["render"]["volume_neighbours"], 4);
    json own = scene;
    own["atmosphere"] = {{"scattering", 0.5}};
    EXPECT_EQ(with_atmosphere(own)["atmosphere"], own["atmosphere"]);
}

}  // namespace
}  // namespace lenslab
