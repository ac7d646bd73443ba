// Reading valid scenes: defaults, both material forms, both lens forms, the example scenes
// and every complete scene shown in docs/scene-format.md.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "geometry/disc.h"
#include "geometry/lens/lens_solid.h"
#include "geometry/rectangle.h"
#include "scene/json_reader.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

namespace fs = std::filesystem;

std::string read_file(const fs::path& p) {
    std::ifstream in(p);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(SceneJson, MinimalSceneGetsTheDocumentedDefaults) {
    const Scene s = parse_scene(R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]}})");
    EXPECT_EQ(s.render.width, 640);
    EXPECT_EQ(s.render.height, 480);
    EXPECT_EQ(s.render.spp, 4);
    EXPECT_EQ(s.render.max_depth, 8);
    EXPECT_EQ(s.render.integrator, "whitted");
    EXPECT_DOUBLE_EQ(s.camera.fov_deg, 40.0);
    EXPECT_NEAR(s.camera.direction.z, -1.0, 1e-15);
    EXPECT_TRUE(s.objects.empty());
}

TEST(SceneJson, TheBenchReadsFilesWithoutACamera) {
    // `lenslab analyze` reads a file of lenses alone; the renderer still needs its camera,
    // and a camera that is given is checked either way.
    const std::string lenses = R"({"objects": [{"type": "lens", "center": [0, 0, 0],
        "axis": [0, 0, 1], "thickness": 5, "diameter": 25,
        "front": {"shape": "sphere", "radius": 50}, "back": {"shape": "flat"},
        "material": {"transparency": 1, "glass": "N-BK7"}}]})";
    const Scene s = parse_scene(lenses, "lenses", "", {.require_camera = false});
    EXPECT_EQ(s.objects.size(), 1u);
    try {
        parse_scene(lenses);
        FAIL() << "a scene without a camera was accepted for rendering";
    } catch (const SceneError& e) {
        EXPECT_STREQ(e.what(), "camera: missing (required)");
    }
    EXPECT_THROW(
        parse_scene(R"({"camera": {"position": [0, 0, 5]}})", "s", "", {.require_camera = false}),
        SceneError);
}

TEST(SceneJson, SppmSettings) {
    const Scene defaults =
        parse_scene(R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]}})");
    EXPECT_EQ(defaults.render.passes, 64);
    EXPECT_EQ(defaults.render.time, 0.0);
    EXPECT_EQ(defaults.render.pass_photons, 0);  // auto
    EXPECT_EQ(defaults.render.initial_radius, 0.0);
    EXPECT_DOUBLE_EQ(defaults.render.alpha, 2.0 / 3.0);
    const Scene s = parse_scene(R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
      "render": {"integrator": "sppm", "passes": 0, "time": 30, "pass_photons": 5000,
                 "initial_radius": 0.02, "alpha": 0.7}})");
    EXPECT_EQ(s.render.integrator, "sppm");
    EXPECT_EQ(s.render.passes, 0);
    EXPECT_EQ(s.render.time, 30.0);
    EXPECT_EQ(s.render.pass_photons, 5000);
    EXPECT_EQ(s.render.initial_radius, 0.02);
    EXPECT_EQ(s.render.alpha, 0.7);
    EXPECT_EQ(parse_scene(R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
                              "render": {"integrator": "path"}})")
                  .render.integrator,
              "path");
}

TEST(SceneJson, NamedAndInlineMaterials) {
    const Scene s = parse_scene(R"({
      "camera": {"position": [0, 0, 5], "direction": [0, 0, -2]},
      "materials": {"glass": {"transparency": 1, "ior": 1.52}},
      "objects": [
        {"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "glass"},
        {"name": "red", "type": "sphere", "center": [3, 0, 0], "radius": 1,
         "material": {"color": [0.9, 0.1, 0.1], "specular": 0.2}}
      ]})");
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_DOUBLE_EQ(s.material_of(0).ior(kLineD), 1.52);
    EXPECT_EQ(s.objects[0].name, "objects[0]");
    EXPECT_EQ(s.objects[1].name, "red");
    EXPECT_DOUBLE_EQ(s.material_of(1).color.r, 0.9);
    EXPECT_DOUBLE_EQ(s.material_of(1).diffuse_weight(), 0.8);
}

TEST(SceneJson, MaterialsTakeTheMakersCatalogueGlasses) {
    // OHARA's data sheet: S-BSL7 n_d 1.51633; HIKARI's SF10 (1.72825) is not SCHOTT's N-SF10.
    const Scene s = parse_scene(R"({
      "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
      "objects": [
        {"type": "sphere", "center": [0, 0, 0], "radius": 1,
         "material": {"transparency": 1, "glass": "s-bsl7"}},
        {"type": "sphere", "center": [3, 0, 0], "radius": 1,
         "material": {"transparency": 1, "glass": "hikari:sf10"}},
        {"type": "sphere", "center": [6, 0, 0], "radius": 1,
         "material": {"transparency": 1, "glass": "N-BK7"}}
      ]})");
    EXPECT_NEAR(s.material_of(0).ior(kLineD), 1.51633, 1e-5);
    EXPECT_EQ(s.material_of(0).glass, "OHARA:S-BSL7");
    EXPECT_NEAR(s.material_of(1).ior(kLineD), 1.72825, 1e-5);
    EXPECT_EQ(s.material_of(1).glass, "HIKARI:SF10");
    EXPECT_EQ(s.material_of(2).glass, "N-BK7");  // the built-in keeps its plain name
}

TEST(SceneJson, ReportLensEqualsItsPrescription) {
    // curvature_radius 1, aperture_radius 0.6 is the prescription R1 = 1, R2 = -1,
    // thickness 2 (1 - sqrt(1 - 0.36)) = 0.4, diameter 1.2.
    const Scene s = parse_scene(R"({
      "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
      "objects": [
        {"type": "lens", "center": [0, 0, 0], "axis": [0, 0, 1], "curvature_radius": 1,
         "aperture_radius": 0.6, "material": {"transparency": 1}},
        {"type": "lens", "center": [0, 0, 0], "axis": [0, 0, 1], "thickness": 0.4, "diameter": 1.2,
         "front": {"shape": "sphere", "radius": 1}, "back": {"shape": "sphere", "radius": -1},
         "material": {"transparency": 1}}
      ]})");
    const auto& a = static_cast<const LensSolid&>(*s.objects[0].shape);
    const auto& b = static_cast<const LensSolid&>(*s.objects[1].shape);
    EXPECT_NEAR(a.prescription().thickness, b.prescription().thickness, 1e-12);
    EXPECT_NEAR(a.prescription().diameter, b.prescription().diameter, 1e-15);
    for (double r = 0; r <= 0.6; r += 0.05) EXPECT_NEAR(a.front_z(r), b.front_z(r), 1e-12);
}

TEST(SceneJson, DiscsRectanglesAndDetectors) {
    const Scene s = parse_scene(R"({
      "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
      "objects": [
        {"type": "disc", "center": [1, 2, 3], "normal": [0, 0, -2], "radius": 0.5, "material": {"color": 0.5}},
        {"type": "rectangle", "center": [0, 0, 0], "normal": [0, 1, 0], "size": [4, 2], "material": {"color": 0.5},
         "detector": true},
        {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "material": {"color": 0.5},
         "detector": {"resolution": [10, 20], "bands": 2, "side": "both", "unit": "mm"}},
        {"type": "disc", "center": [0, 0, 0], "normal": [1, 0, 0], "radius": 1, "up": [0, 0, 1],
         "material": {"color": 0.5}, "detector": false}
      ]})");
    ASSERT_EQ(s.objects.size(), 4u);
    const auto& disc = dynamic_cast<const Disc&>(*s.objects[0].shape);
    EXPECT_DOUBLE_EQ(disc.radius(), 0.5);
    EXPECT_DOUBLE_EQ(disc.normal().z, -1.0);  // normalised
    EXPECT_FALSE(s.objects[0].detector);
    // A floor (normal +y) gets the default up -z: u along +x.
    const auto& rect = dynamic_cast<const Rectangle&>(*s.objects[1].shape);
    EXPECT_DOUBLE_EQ(rect.width(), 4.0);
    EXPECT_NEAR(rect.frame().u.x, 1.0, 1e-15);
    EXPECT_NEAR(rect.frame().v.z, -1.0, 1e-15);
    ASSERT_TRUE(s.objects[1].detector);
    const DetectorSettings& d = *s.objects[1].detector;
    EXPECT_EQ(d.resolution_long, 64);
    EXPECT_EQ(d.band_edges, (std::vector<double>{360, 490, 585, 830}));
    EXPECT_EQ(d.side, DetectorSide::Front);
    EXPECT_EQ(d.unit, "unit");
    ASSERT_TRUE(s.objects[2].detector);
    const DetectorSettings& t = *s.objects[2].detector;
    EXPECT_EQ(t.cells_u, 10);
    EXPECT_EQ(t.cells_v, 20);
    EXPECT_EQ(t.band_edges, (std::vector<double>{360, 595, 830}));
    EXPECT_EQ(t.side, DetectorSide::Both);
    EXPECT_EQ(t.unit, "mm");
    EXPECT_FALSE(s.objects[3].detector);
    const auto& turned = dynamic_cast<const Disc&>(*s.objects[3].shape);
    EXPECT_NEAR(turned.frame().v.z, 1.0, 1e-15);
}

TEST(SceneJson, CompiledInDefaultSceneIsScenesDefaultJson) {
    EXPECT_EQ(default_scene_text(),
              read_file(fs::path(LENSLAB_SOURCE_DIR) / "scenes/default.json"));
}

TEST(SceneJson, EveryExampleSceneLoads) {
    int count = 0;
    for (const auto& entry : fs::directory_iterator(fs::path(LENSLAB_SOURCE_DIR) / "scenes")) {
        if (entry.path().extension() != ".json") continue;
        SCOPED_TRACE(entry.path().string());
        EXPECT_NO_THROW(load_scene_file(entry.path().string()));
        ++count;
    }
    EXPECT_GE(count, 3);
}

// Every complete scene (a JSON block with a camera) in the format reference must load, so
// the documentation cannot drift from the reader. Files they name (an OBJ mesh) are looked
// up in scenes/, where the examples say to save them.
TEST(SceneJson, DocumentedExamplesLoad) {
    const std::string doc = read_file(fs::path(LENSLAB_SOURCE_DIR) / "docs/scene-format.md");
    const std::regex block("```json\\n([\\s\\S]*?)```");
    int complete = 0;
    for (std::sregex_iterator it(doc.begin(), doc.end(), block), end; it != end; ++it) {
        const std::string text = (*it)[1].str();
        nlohmann::json j;
        ASSERT_NO_THROW(j = nlohmann::json::parse(text)) << text;
        if (!j.is_object() || !j.contains("camera")) continue;
        EXPECT_NO_THROW(parse_scene(text, "docs", std::string(LENSLAB_SOURCE_DIR) + "/scenes"))
            << text;
        ++complete;
    }
    EXPECT_GE(complete, 2);
}

}  // namespace
}  // namespace lenslab
