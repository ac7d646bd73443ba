// The named-material edits (scene/material_edits.h) on JSON documents: renames follow every
// use, deletes refuse while a material is in use, "make unique" detaches one use, and every
// edited document still reads as a scene with the materials it should have.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "scene/material_edits.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

using nlohmann::json;

// The default scene's situation: a sphere and a lens share "glass"; a lens group's element
// names a material too.
json shared_glass_scene() {
    return json::parse(R"json({
      "camera": {"position": [0, 1, -5], "look_at": [0, 1, 0], "fov": 40},
      "materials": {"glass": {"color": 1, "transparency": 1, "ior": 1.5},
                    "white": {"color": 0.8}},
      "objects": [
        {"type": "sphere", "name": "ball", "center": [0, 1, 0], "radius": 0.4, "material": "glass"},
        {"type": "lens", "name": "lens", "center": [1, 1, 0], "axis": [0, 1, 0],
         "curvature_radius": 1, "aperture_radius": 0.4, "material": "glass"},
        {"type": "lens_group", "name": "doublet", "vertex": [0, 2, 0], "axis": [0, 0, 1],
         "diameter": 0.5, "elements": [{"front": {"shape": "sphere", "radius": 1}, "thickness": 0.1,
         "back": {"shape": "sphere", "radius": -1}, "material": "glass"}]},
        {"type": "sphere", "center": [0, -100, 0], "radius": 99, "material": "white"}
      ],
      "lights": [{"type": "point", "position": [0, 5, 0], "power": 100}]
    })json");
}

// The materials the scene's objects end up with, by reading the document as lenslab does.
double material_index(const json& doc, int object) {
    const Scene s = scene_from_json(doc);
    return s.material_of(object).index->n_d();
}

TEST(MaterialEdits, UsersAreEveryObjectAndElementNamingIt) {
    const json doc = shared_glass_scene();
    EXPECT_EQ(material_users(doc, "glass"),
              (std::vector<std::string>{"/objects/0/material", "/objects/1/material",
                                        "/objects/2/elements/0/material"}));
    EXPECT_EQ(material_users(doc, "white"), std::vector<std::string>{"/objects/3/material"});
    EXPECT_TRUE(material_users(doc, "nothing").empty());
}

TEST(MaterialEdits, RenameFollowsEveryUse) {
    const json doc = rename_material(shared_glass_scene(), "glass", "crown");
    EXPECT_FALSE(doc["materials"].contains("glass"));
    EXPECT_EQ(doc["materials"]["crown"]["ior"], 1.5);
    EXPECT_EQ(material_users(doc, "crown").size(), 3u);
    EXPECT_NO_THROW(scene_from_json(doc));
}

TEST(MaterialEdits, RenameRefusesATakenOrEmptyName) {
    const json doc = shared_glass_scene();
    EXPECT_THROW(rename_material(doc, "glass", "white"), MaterialEditError);
    EXPECT_THROW(rename_material(doc, "glass", ""), MaterialEditError);
    EXPECT_THROW(rename_material(doc, "flint", "x"), MaterialEditError);
    EXPECT_EQ(rename_material(doc, "glass", "glass"), doc);
}

TEST(MaterialEdits, DeleteRefusesWhileInUseAndNamesTheUsers) {
    const json doc = shared_glass_scene();
    try {
        delete_material(doc, "glass");
        FAIL() << "deleted a material in use";
    } catch (const MaterialEditError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "'glass' is used by 'ball', 'lens', 'doublet': give them another material first");
    }
    // With a replacement, its users take that one.
    const json replaced = delete_material(doc, "glass", "white");
    EXPECT_FALSE(replaced["materials"].contains("glass"));
    EXPECT_EQ(material_users(replaced, "white").size(), 4u);
    // An unused one goes.
    const json added = add_material(doc, "spare", nullptr);
    EXPECT_FALSE(delete_material(added, "spare")["materials"].contains("spare"));
}

TEST(MaterialEdits, MakeUniqueDetachesOneUse) {
    // The issue's bug: the sphere and the lens share "glass", so an index typed for the
    // sphere changed the lens too. Made unique, the sphere's edit stays its own.
    std::string added;
    json doc = make_material_unique(shared_glass_scene(), "/objects/0/material", &added);
    EXPECT_EQ(added, "glass 2");
    EXPECT_EQ(doc["objects"][0]["material"], "glass 2");
    EXPECT_EQ(doc["objects"][1]["material"], "glass");
    doc["materials"]["glass 2"]["ior"] = 2.4;
    EXPECT_DOUBLE_EQ(material_index(doc, 0), 2.4);
    EXPECT_DOUBLE_EQ(material_index(doc, 1), 1.5);
    EXPECT_THROW(make_material_unique(doc, "/objects/0/center", nullptr), MaterialEditError);
}

TEST(MaterialEdits, NewAndDuplicatedNamesAreUnique) {
    std::string a, b, c;
    json doc = add_material(shared_glass_scene(), "", &a);
    doc = add_material(doc, "", &b);
    doc = duplicate_material(doc, "glass", &c);
    EXPECT_EQ(a, "material");
    EXPECT_EQ(b, "material 2");
    EXPECT_EQ(c, "glass copy");
    EXPECT_EQ(doc["materials"]["glass copy"], doc["materials"]["glass"]);
    EXPECT_NO_THROW(scene_from_json(doc));
}

}  // namespace
}  // namespace lenslab
