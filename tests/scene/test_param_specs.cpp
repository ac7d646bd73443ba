// Each element type's declaration (param_spec.h) against everything that repeats it: the
// reference table in docs/scene-format.md, the scene reader's defaults and bounds, and the
// help of `lenslab render`'s generated options. A docs default or range edited by hand, or a
// reader check that drifts from the declaration, fails here.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "scene/box_json.h"
#include "scene/camera_spec.h"
#include "scene/json_reader.h"
#include "scene/lens_group_json.h"
#include "scene/light_spec.h"
#include "scene/light_types.h"
#include "scene/material_spec.h"
#include "scene/medium.h"
#include "scene/mesh_json.h"
#include "scene/object_spec.h"
#include "scene/object_types.h"
#include "scene/param_spec.h"
#include "scene/planar_json.h"
#include "scene/render_settings_spec.h"
#include "scene/scene_json.h"
#include "scene/surface_json.h"
#include "scene/surface_shapes.h"

namespace {

using lenslab::ElementSpec;
using lenslab::ParamKind;
using lenslab::ParamSpec;
using nlohmann::json;

std::string trim(const std::string& s) {
    const size_t a = s.find_first_not_of(' ');
    const size_t b = s.find_last_not_of(' ');
    return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

std::vector<std::string> cells(const std::string& row) {
    std::vector<std::string> out;
    std::stringstream in(row.substr(1));  // after the leading '|'
    std::string cell;
    while (std::getline(in, cell, '|')) out.push_back(trim(cell));
    return out;
}

// The reference table after the line `anchor` (a heading, or the sentence introducing it)
// in docs/scene-format.md: key -> its cells (key, type, default, range, meaning).
std::map<std::string, std::vector<std::string>> docs_table(const std::string& anchor) {
    std::ifstream docs(LENSLAB_SOURCE_DIR "/docs/scene-format.md");
    std::string line;
    while (std::getline(docs, line) && line != anchor) {
    }
    EXPECT_EQ(line, anchor) << "not in docs/scene-format.md";
    while (std::getline(docs, line) && line.rfind("| key |", 0) != 0) {
    }
    EXPECT_EQ(line, "| key | type | default | range | meaning |") << "after " << anchor;
    std::getline(docs, line);  // | --- | ...
    std::map<std::string, std::vector<std::string>> rows;
    while (std::getline(docs, line) && line.rfind("|", 0) == 0) {
        std::vector<std::string> row = cells(line);
        const std::string key = row.at(0).substr(1, row.at(0).size() - 2);  // `key`
        rows[key] = row;
    }
    return rows;
}

struct Case {
    const ElementSpec& (*spec)();
    std::string anchor;                  // the docs line its table follows
    json scene;                          // a valid scene holding one such element ...
    const char* pointer;                 // ... here
    const char* path;                    // which messages call
    std::vector<std::string> elsewhere;  // keys documented in another table
    // The test's name when one declaration has several cases (the lens's two forms).
    std::string name = "";
    // Keys whose bounds another case checks (they belong to the other form).
    std::vector<std::string> unread = {};
};

std::vector<Case> cases() {
    const json camera = {{"position", {0, 0, 5}}, {"look_at", {0, 0, 0}}};
    const json sphere = {
        {"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 1}, {"material", "m"}};
    const json scene = {{"camera", camera},
                        {"render", {{"time", 1}}},  // so passes 0 alone is not what refuses a value
                        {"materials", {{"m", {{"emission", {{"intensity", 1}}}}}}},
                        {"objects", json::array({sphere})},
                        {"lights", {{{"type", "point"}, {"position", {0, 2, 0}}, {"power", 1}}}}};
    json with_beam = scene;
    with_beam["lights"] = {{{"type", "beam"},
                            {"origin", {0, 2, 0}},
                            {"direction", {0, -1, 0}},
                            {"radius", 0.1},
                            {"power", 1}}};
    json with_laser = scene;
    with_laser["lights"] = {{{"type", "laser"},
                             {"position", {0, 2, 0}},
                             {"direction", {0, -1, 0}},
                             {"radius", 0.01},
                             {"power", 1}}};
    json with_spot = scene;
    with_spot["lights"] = {
        {{"type", "spot"}, {"position", {0, 2, 0}}, {"direction", {0, -1, 0}}, {"power", 1}}};
    json with_rectangle_light = scene;
    with_rectangle_light["lights"] = {{{"type", "rectangle_light"},
                                       {"center", {0, 2, 0}},
                                       {"normal", {0, -1, 0}},
                                       {"size", {1, 0.5}},
                                       {"power", 1}}};
    json with_disc_light = scene;
    with_disc_light["lights"] = {{{"type", "disc_light"},
                                  {"center", {0, 2, 0}},
                                  {"normal", {0, -1, 0}},
                                  {"radius", 0.3},
                                  {"power", 1}}};
    json with_atmosphere = scene;
    with_atmosphere["atmosphere"] = {{"scattering", 0.1}};
    json with_grin = scene;
    with_grin["materials"]["m"] = {
        {"transparency", 1},
        {"grin", {{"profile", "luneburg"}, {"radius", 1}, {"formula", "1.5"}}}};
    json with_implicit = scene;
    with_implicit["objects"] = {{{"type", "implicit"},
                                 {"formula", "x^2 + y^2 + z^2 - 0.25"},
                                 {"bounds", {{-1, -1, -1}, {1, 1, 1}}},
                                 {"material", {{"color", 0.5}}}}};
    json with_disc = scene;
    with_disc["objects"] = {{{"type", "disc"},
                             {"center", {0, 0, 0}},
                             {"normal", {0, 0, 1}},
                             {"radius", 1},
                             {"material", {{"color", 0.5}}}}};
    json with_triangle = with_disc;
    with_triangle["objects"][0] = {{"type", "triangle"},
                                   {"vertices", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}},
                                   {"material", {{"color", 0.5}}}};
    json with_rectangle = with_disc;
    with_rectangle["objects"][0].erase("radius");
    with_rectangle["objects"][0]["type"] = "rectangle";
    with_rectangle["objects"][0]["size"] = {1, 2};
    json with_box = scene;
    with_box["objects"] = {{{"type", "box"},
                            {"center", {0, 0, 0}},
                            {"size", {1, 2, 3}},
                            {"material", {{"color", 0.5}}}}};
    const json glass_free = {{"color", 0.5}};
    json with_report_lens = scene;
    with_report_lens["objects"] = {{{"type", "lens"},
                                    {"center", {0, 0, 0}},
                                    {"axis", {0, 0, 1}},
                                    {"curvature_radius", 1},
                                    {"aperture_radius", 0.5},
                                    {"material", glass_free}}};
    json with_lens = scene;
    with_lens["objects"] = {{{"type", "lens"},
                             {"center", {0, 0, 0}},
                             {"axis", {0, 0, 1}},
                             {"thickness", 0.5},
                             {"diameter", 1},
                             {"front", {{"shape", "sphere"}, {"radius", 2}}},
                             {"back", {{"shape", "sphere"}, {"radius", -2}}},
                             {"material", glass_free}}};
    const auto with_front = [&with_lens](const json& surface) {
        json out = with_lens;
        out["objects"][0]["front"] = surface;
        return out;
    };
    json with_mesh = scene;
    with_mesh["objects"] = {{{"type", "mesh"},
                             {"vertices", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}},
                             {"faces", {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}},
                             {"material", glass_free}}};
    json with_prism = scene;
    with_prism["objects"] = {{{"type", "prism"},
                              {"side", 1},
                              {"height", 1},
                              {"center", {0, 0, 0}},
                              {"material", glass_free}}};
    json with_group = scene;
    with_group["objects"] = {{{"type", "lens_group"},
                              {"vertex", {0, 0, 0}},
                              {"axis", {0, 0, 1}},
                              {"diameter", 1},
                              {"elements",
                               {{{"front", {{"shape", "sphere"}, {"radius", 2}}},
                                 {"back", {{"shape", "sphere"}, {"radius", -2}}},
                                 {"thickness", 0.5},
                                 {"material", glass_free}}}}}};
    json with_mirror_group = with_group;
    // A lens, then the mirror (a first element cannot be tilted).
    with_mirror_group["objects"][0]["elements"][0]["gap"] = 1;
    with_mirror_group["objects"][0]["elements"].push_back(
        {{"mirror", {{"shape", "conic"}, {"radius", -4}, {"k", -1}}},
         {"material", {{"color", 0}, {"specular", 1}}}});
    json with_detector = with_disc;
    with_detector["objects"][0]["detector"] = json::object();
    const std::vector<std::string> common = lenslab::object_common_spec().keys();
    const std::vector<std::string> report{"curvature_radius", "aperture_radius"};
    const std::vector<std::string> prescription{"thickness", "diameter"};
    const std::vector<std::string> group_common{"type", "name", "photon_target"};
    std::vector<Case> out{
        {lenslab::render_settings_spec, "## Render", scene, "/render", "render", {}},
        {lenslab::camera_spec, "## Camera", scene, "/camera", "camera", {}},
        {lenslab::material_spec, "## Materials", scene, "/materials/m", "materials.m", {}},
        {lenslab::emission_spec,
         "`emission` has three keys:",
         scene,
         "/materials/m/emission",
         "materials.m.emission",
         {}},
        {lenslab::grin_spec,
         "`grin` has these keys:",
         with_grin,
         "/materials/m/grin",
         "materials.m.grin",
         {}},
        {lenslab::point_light_spec,
         "A point light (`\"type\": \"point\"`):",
         scene,
         "/lights/0",
         "lights[0]",
         {}},
        {lenslab::beam_spec,
         "A beam (`\"type\": \"beam\"`):",
         with_beam,
         "/lights/0",
         "lights[0]",
         {}},
        {lenslab::laser_spec,
         "A laser (`\"type\": \"laser\"`):",
         with_laser,
         "/lights/0",
         "lights[0]",
         {}},
        {lenslab::spot_light_spec,
         "A spot light (`\"type\": \"spot\"`):",
         with_spot,
         "/lights/0",
         "lights[0]",
         {}},
        // The area lights declare themselves in their own files, reached through the table.
        {[]() -> const ElementSpec& { return *lenslab::find_light_spec("rectangle_light"); },
         "A rectangle light (`\"type\": \"rectangle_light\"`):",
         with_rectangle_light,
         "/lights/0",
         "lights[0]",
         {}},
        {[]() -> const ElementSpec& { return *lenslab::find_light_spec("disc_light"); },
         "A disc light (`\"type\": \"disc_light\"`):",
         with_disc_light,
         "/lights/0",
         "lights[0]",
         {}},
        {lenslab::medium_spec, "## Atmosphere", with_atmosphere, "/atmosphere", "atmosphere", {}},
        {lenslab::object_common_spec, "## Objects", scene, "/objects/0", "objects[0]", {}},
        {lenslab::sphere_spec, "### Sphere", scene, "/objects/0", "objects[0]", common},
        {lenslab::implicit_spec, "### Implicit solid", with_implicit, "/objects/0", "objects[0]",
         common},
        {lenslab::triangle_spec, "### Triangle", with_triangle, "/objects/0", "objects[0]", common},
        {lenslab::disc_spec, "### Disc", with_disc, "/objects/0", "objects[0]", common},
        {lenslab::rectangle_spec, "### Rectangle", with_rectangle, "/objects/0", "objects[0]",
         common},
        {lenslab::box_spec, "### Box", with_box, "/objects/0", "objects[0]", common},
        {lenslab::lens_spec, "### Lens", with_report_lens, "/objects/0", "objects[0]", common,
         "lens_report_form", prescription},
        {lenslab::lens_spec, "### Lens", with_lens, "/objects/0", "objects[0]", common,
         "lens_prescription_form", report},
        {lenslab::mesh_spec, "### Mesh", with_mesh, "/objects/0", "objects[0]", common},
        {lenslab::prism_spec, "### Prism", with_prism, "/objects/0", "objects[0]", common},
        {lenslab::lens_group_spec, "### Lens group", with_group, "/objects/0", "objects[0]",
         group_common},
        {lenslab::lens_group_element_spec,
         "Each element:",
         with_group,
         "/objects/0/elements/0",
         "objects[0].elements[0]",
         {}},
        {lenslab::lens_group_mirror_spec,
         "Each mirror element:",
         with_mirror_group,
         "/objects/0/elements/1",
         "objects[0].elements[1]",
         {}},
        {lenslab::detector_spec,
         "`\"detector\": true` takes every default; an object sets any of:",
         with_detector,
         "/objects/0/detector",
         "objects[0].detector",
         {}},
    };
    // Each lens surface shape declares itself in its own file, with an example, reached
    // through the table: a new shape is checked against its docs table without a line here.
    for (const lenslab::SurfaceShapeEntry& e : lenslab::surface_shapes()) {
        // "A `"flat"` surface:", "An `"asphere"` surface:", "An `"xy_polynomial"` surface:"
        const bool an = std::string_view("aeiox").find(e.name[0]) != std::string_view::npos;
        const std::string article = an ? "An" : "A";
        const std::string anchor = article + " `\"" + e.name + "\"` surface:";
        out.push_back({e.spec,
                       anchor,
                       with_front(e.spec().example),
                       "/objects/0/front",
                       "objects[0].front",
                       {}});
    }
    return out;
}

class DeclaredElement : public testing::TestWithParam<Case> {};

TEST_P(DeclaredElement, DocsTableAgreesWithTheDeclaration) {
    const ElementSpec& spec = GetParam().spec();
    auto rows = docs_table(GetParam().anchor);
    for (const ParamSpec& p : spec.params) {
        const auto& elsewhere = GetParam().elsewhere;
        if (std::find(elsewhere.begin(), elsewhere.end(), p.key) != elsewhere.end()) continue;
        const auto it = rows.find(p.key);
        ASSERT_NE(it, rows.end()) << spec.name << "." << p.key << " is not in the docs table";
        const std::vector<std::string>& row = it->second;
        ASSERT_GE(row.size(), 5u) << spec.name << "." << p.key;
        EXPECT_EQ(row[1], lenslab::kind_text(p)) << spec.name << "." << p.key << ": type";
        EXPECT_EQ(row[2], lenslab::default_text(p)) << spec.name << "." << p.key << ": default";
        EXPECT_EQ(row[3], lenslab::range_text(p)) << spec.name << "." << p.key << ": range";
        rows.erase(it);
    }
    for (const auto& [key, row] : rows) ADD_FAILURE() << "docs list " << key << ", not declared";
}

// Reads the case's scene with the element's `key` set to `value` (removed for null): "" when
// accepted, else the error.
std::string read_with(const Case& c, const std::string& key, const json& value) {
    json scene = c.scene;
    json& element = scene[json::json_pointer(c.pointer)];
    if (value.is_null()) {
        element.erase(key);
    } else {
        element[key] = value;
    }
    try {
        (void)lenslab::scene_from_json(scene);
        return "";
    } catch (const lenslab::SceneError& e) {
        return e.what();
    }
}

TEST_P(DeclaredElement, ReaderAcceptsDefaultsAndRefusesPastTheBounds) {
    const Case& c = GetParam();
    for (const ParamSpec& p : c.spec().params) {
        if (std::find(c.unread.begin(), c.unread.end(), p.key) != c.unread.end()) continue;
        const std::string path = std::string(c.path) + "." + p.key + ": ";
        if (p.required) {
            EXPECT_EQ(read_with(c, p.key, nullptr), path + "missing (required)");
        }
        if (!p.fallback.is_null() && lenslab::fallback_in_range(p)) {
            EXPECT_EQ(read_with(c, p.key, p.fallback), "") << "the default of " << path;
        }
        for (const std::string& choice : p.choices) {
            EXPECT_EQ(read_with(c, p.key, choice), "");
        }
        if (p.kind == ParamKind::Choice) {
            EXPECT_EQ(read_with(c, p.key, "bogus"), path + *lenslab::choice_problem(p, "bogus"));
        }
        if (p.kind != ParamKind::Number && p.kind != ParamKind::WholeNumber &&
            p.kind != ParamKind::Fraction) {
            continue;
        }
        // Just past each end: the next whole number, or a small step for other numbers.
        const auto past = [&p](double bound, double direction) {
            return bound +
                   direction * (p.is_integer() ? 1.0 : 1e-9 * std::max(1.0, std::abs(bound)));
        };
        const auto check_end = [&](const lenslab::Bound& b, double outwards) {
            const double outside = b.exclusive ? b.value : past(b.value, outwards);
            const json written = p.is_integer() ? json(int64_t(outside)) : json(outside);
            EXPECT_EQ(read_with(c, p.key, written), path + *lenslab::range_problem(p, outside));
            if (!b.exclusive) {
                const json at = p.is_integer() ? json(int64_t(b.value)) : json(b.value);
                EXPECT_EQ(read_with(c, p.key, at), "") << path << "at the bound " << b.value;
            }
        };
        // A fraction's [0, 1] holds whatever else it declares.
        const bool fraction = p.kind == ParamKind::Fraction;
        if (p.min) check_end(*p.min, -1.0);
        if (fraction && !p.min) check_end(lenslab::Bound{0.0}, -1.0);
        if (p.max) check_end(*p.max, 1.0);
        if (fraction) check_end(lenslab::Bound{1.0}, 1.0);
    }
}

INSTANTIATE_TEST_SUITE_P(Elements, DeclaredElement, testing::ValuesIn(cases()),
                         [](const testing::TestParamInfo<Case>& element) {
                             std::string name = element.param.name.empty()
                                                    ? element.param.spec().name
                                                    : element.param.name;
                             std::replace(name.begin(), name.end(), ' ', '_');
                             return name;
                         });

// Every object type is read through a declaration, and its section's table lists exactly the
// declared keys that are not common to every object (those are in the "Objects" table, whose
// `type` row names every type).
TEST(ObjectTypes, EachIsDeclaredAndItsDocsTableHasItsKeys) {
    const std::map<std::string, std::string> section{{"sphere", "### Sphere"},
                                                     {"triangle", "### Triangle"},
                                                     {"disc", "### Disc"},
                                                     {"rectangle", "### Rectangle"},
                                                     {"lens", "### Lens"},
                                                     {"lens_group", "### Lens group"},
                                                     {"mesh", "### Mesh"},
                                                     {"prism", "### Prism"},
                                                     {"implicit", "### Implicit solid"},
                                                     {"box", "### Box"},
                                                     {"mirror", "### Mirror"}};
    const auto objects = docs_table("## Objects");
    for (const lenslab::ObjectTypeEntry& e : lenslab::object_types()) {
        ASSERT_NE(e.spec, nullptr) << e.name << " is not declared";
        EXPECT_NE(objects.at("type").at(4).find("`\"" + e.name + "\"`"), std::string::npos)
            << "the Objects table's type row does not name " << e.name;
        const auto it = section.find(e.name);
        ASSERT_NE(it, section.end()) << e.name << ": which docs section?";
        std::set<std::string> own, documented;
        for (const std::string& key : e.spec().keys()) {
            if (!lenslab::is_common_object_key(key)) own.insert(key);
        }
        for (const auto& [key, row] : docs_table(it->second)) documented.insert(key);
        EXPECT_EQ(own, documented) << e.name;
    }
}

std::string run_and_capture(const std::string& command) {
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
    std::string out;
    std::array<char, 4096> buffer{};
    while (pipe && fgets(buffer.data(), buffer.size(), pipe.get())) out += buffer.data();
    return out;
}

// The option names are a contract with scripts; the declaration generates exactly these.
TEST(RenderOptions, AreTheDeclaredKeysWithTheirRangesInTheHelp) {
    std::vector<std::string> contract{"--width",
                                      "--height",
                                      "--spp",
                                      "--max-depth",
                                      "--seed",
                                      "--integrator",
                                      "--dispersion-samples",
                                      "--merge-weight",
                                      "--photons",
                                      "--caustic-photons",
                                      "--aim-photons",
                                      "--radius",
                                      "--filter",
                                      "--direct",
                                      "--filter-k",
                                      "--max-photons-per-estimate",
                                      "--passes",
                                      "--time",
                                      "--pass-photons",
                                      "--initial-radius",
                                      "--volume-neighbours",
                                      "--tone-map",
                                      "--highlight-stops"};
    std::vector<std::string> declared;
    for (const ParamSpec& p : lenslab::render_settings_spec().params) {
        if (p.cli) declared.push_back(p.option_name());
    }
    std::sort(declared.begin(), declared.end());
    std::sort(contract.begin(), contract.end());
    EXPECT_EQ(declared, contract);

    const std::string help = run_and_capture(std::string(LENSLAB_BINARY) + " render --help");
    ASSERT_NE(help.find("--seed"), std::string::npos) << help;
    for (const ParamSpec& p : lenslab::render_settings_spec().params) {
        if (!p.cli) continue;
        // CLI11 may wrap a long description: the option's text runs to the next option.
        const size_t at = help.find("  " + p.option_name() + " ");
        ASSERT_NE(at, std::string::npos) << p.option_name() << " not in\n" << help;
        const std::string entry = help.substr(at, help.find("\n  --", at + 1) - at);
        std::string range = p.kind == ParamKind::Boolean ? "on or off" : lenslab::range_text(p);
        range.erase(std::remove(range.begin(), range.end(), '`'), range.end());
        EXPECT_NE(entry.find(range), std::string::npos) << p.option_name() << ": " << entry;
        EXPECT_NE(entry.find(p.doc), std::string::npos) << p.option_name() << ": " << entry;
    }
}

// Each object and light type declares the element the editor's "Add" starts from; placed
// anywhere, it is a scene the reader accepts, and it lands where it was put.
TEST(Examples, EveryTypeHasOneTheReaderAcceptsWhereverItIsPut) {
    std::vector<const ElementSpec*> specs;
    for (const lenslab::ObjectTypeEntry& t : lenslab::object_types()) specs.push_back(&t.spec());
    for (const ElementSpec* l : lenslab::light_specs()) specs.push_back(l);
    ASSERT_EQ(specs.size(), lenslab::object_types().size() + lenslab::light_types().size());
    const lenslab::Vec3 at{2, -1, 7};
    for (const ElementSpec* spec : specs) {
        SCOPED_TRACE(spec->name);
        ASSERT_TRUE(spec->example.is_object());
        const bool light = lenslab::find_light_spec(spec->example.at("type")) == spec;
        json scene{{"camera", {{"position", {0, 0, 20}}, {"look_at", {0, 0, 0}}}},
                   {light ? "lights" : "objects", {moved_element(*spec, spec->example, at)}}};
        lenslab::Scene read;
        ASSERT_NO_THROW(read = lenslab::scene_from_json(scene)) << scene.dump();
        if (light) {
            ASSERT_EQ(read.lights().size(), 1u);
            continue;
        }
        // The object's box holds the point it was put at (every example surrounds its origin).
        const lenslab::Aabb box = read.bounds();
        for (int a = 0; a < 3; ++a) {
            EXPECT_LE(box.lo[a], at[a] + 1e-9);
            EXPECT_GE(box.hi[a], at[a] - 1e-9);
        }
    }
}

// A quarter turn about +y through (1, 0, 0): x -> -z about the pivot, and directions turn.
TEST(Examples, RotatingAnElementTurnsItsPointsAndDirections) {
    using lenslab::rotated_element;
    const double quarter = std::acos(0.0);
    const auto near = [](const json& got, std::initializer_list<double> want) {
        std::vector<double> w(want);
        for (size_t a = 0; a < 3; ++a) EXPECT_NEAR(got[a].get<double>(), w[a], 1e-12) << got;
    };
    const json lens =
        rotated_element(lenslab::lens_spec(), {{"center", {2, 1, 0}}, {"axis", {1, 0, 0}}},
                        {1, 0, 0}, {0, 1, 0}, quarter);
    near(lens["center"], {1, 1, -1});
    near(lens["axis"], {0, 0, -1});
    const json triangle =
        rotated_element(lenslab::triangle_spec(), {{"vertices", {{1, 0, 0}, {2, 0, 0}, {1, 1, 0}}}},
                        {1, 0, 0}, {0, 1, 0}, quarter);
    near(triangle["vertices"][1], {1, 0, -1});
    near(triangle["vertices"][2], {1, 1, 0});
    // A box's absent up and facing are written out turned; a rectangle's automatic up too,
    // so a turn about its normal shows.
    const json box = rotated_element(lenslab::box_spec(), {{"center", {1, 0, 0}}}, {1, 0, 0},
                                     {0, 1, 0}, quarter);
    near(box["facing"], {1, 0, 0});
    near(box["up"], {0, 1, 0});
    const json rectangle =
        rotated_element(lenslab::rectangle_spec(), {{"center", {0, 0, 0}}, {"normal", {0, 0, 1}}},
                        {0, 0, 0}, {0, 0, 1}, quarter);
    near(rectangle["normal"], {0, 0, 1});
    near(rectangle["up"], {-1, 0, 0});
    // A line laser's automatic fan axis (horizontal, -z for a beam along +x) is written out
    // turned, so a turn about the beam stands the fan up; a laser without a fan gets none.
    const json fan =
        rotated_element(lenslab::laser_spec(),
                        {{"position", {0, 0, 0}}, {"direction", {1, 0, 0}}, {"fan_angle", 30}},
                        {0, 0, 0}, {1, 0, 0}, quarter);
    near(fan["direction"], {1, 0, 0});
    near(fan["fan_axis"], {0, 1, 0});
    EXPECT_FALSE(fan.contains("slit_axis"));
    EXPECT_TRUE(lenslab::element_turns(lenslab::lens_spec()));
    EXPECT_FALSE(lenslab::element_turns(lenslab::sphere_spec()));
    EXPECT_FALSE(lenslab::element_turns(lenslab::implicit_spec()));
}

TEST(Examples, MovingAnElementMovesItsPositionsAndNothingElse) {
    using lenslab::moved_element;
    const json triangle = moved_element(lenslab::triangle_spec(),
                                        {{"type", "triangle"},
                                         {"vertices", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}},
                                         {"material", {{"color", 0.5}}}},
                                        {1, 2, 3});
    EXPECT_EQ(triangle["vertices"], json({{1, 2, 3}, {2, 2, 3}, {1, 3, 3}}));
    EXPECT_EQ(triangle["material"], json({{"color", 0.5}}));
    // An absent position with a declared default is written out, moved.
    const json torus = moved_element(lenslab::implicit_spec(), {{"type", "implicit"}}, {0.5, 0, 0});
    EXPECT_EQ(torus["center"], json({0.5, 0, 0}));
    const json disc = moved_element(lenslab::disc_spec(),
                                    {{"center", {1, 1, 1}}, {"normal", {0, 0, 1}}}, {1, 0, 0});
    EXPECT_EQ(disc["center"], json({2, 1, 1}));
    EXPECT_EQ(disc["normal"], json({0, 0, 1}));  // a direction stays
    // A value of the wrong shape is left for the reader to refuse.
    const json bad = moved_element(lenslab::sphere_spec(), {{"center", "here"}}, {1, 0, 0});
    EXPECT_EQ(bad["center"], "here");
}

}  // namespace
