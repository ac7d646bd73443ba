// The declarations of the flat shapes (planar_json.h), next to their reader.

#include "scene/object_spec.h"
#include "scene/planar_json.h"

namespace lenslab {

namespace {

// Where a flat shape lies and which way it faces; the rectangle takes the same.
void add_frame(ElementSpec& s, const std::string& normal_doc) {
    s.params.push_back(point_param("center").describe("centre").in_editor("Centre"));
    s.params.push_back(direction_param("normal").describe(normal_doc).in_editor("Normal (front)"));
}

// The default up depends on the normal, so it is described rather than given.
ParamSpec up_param(const std::string& doc) {
    return vector_param(ParamKind::Direction, "up", nullptr)
        .meaning_auto("`[0, 1, 0]`, or `[0, 0, -1]` when the normal is vertical")
        .describe(doc)
        .in_editor("Up (orients u, v)");
}

ElementSpec declare_disc() {
    ElementSpec s = shape_spec("disc", "a disc", true);
    add_frame(s, "the side the disc faces: its front");
    s.params.push_back(
        number_param("radius", 0).above(0).needed().describe("radius").in_editor("Radius", 9));
    s.params.push_back(up_param("orients the disc's own coordinates (u, v)"));
    s.example = nlohmann::json::parse(
        R"json({"type": "disc", "name": "detector disc", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 0.5, "material": {"color": 0.7}, "detector": {"resolution": 64}})json");
    return s;
}

ElementSpec declare_rectangle() {
    ElementSpec s = shape_spec("rectangle", "a rectangle", true);
    add_frame(s, "the side it faces (its front)");
    s.params.push_back(nested_param(ParamKind::Array, "size")
                           .needed()
                           .as_written("`[width, height]`, each `> 0`")
                           .describe("width along u, height along v"));
    s.params.push_back(up_param("which way the height runs"));
    s.example = nlohmann::json::parse(
        R"json({"type": "rectangle", "name": "detector screen", "center": [0, 0, 0], "normal": [0, 0, 1], "size": [1, 1], "material": {"color": 0.7}, "detector": {"resolution": 64}})json");
    return s;
}

// A detector's cells and bands are a number or an array, so their kind is an array (read by
// planar_json.cpp); the cell count's range is declared here all the same.
ElementSpec declare_detector() {
    // No phrase: a key it does not take is an "unknown key", as in any nested object.
    ElementSpec s{"detector", "", {}, {}};
    s.params.push_back(vector_param(ParamKind::Array, "resolution", 64)
                           .at_least(1)
                           .at_most(1024)
                           .as_written("whole number, or `[cells_u, cells_v]`")
                           .describe("cells across the detector; each count in the range"));
    s.params.push_back(
        vector_param(ParamKind::Array, "bands", nlohmann::json::array({360, 490, 585, 830}))
            .as_written("whole number, or array of wavelengths (nm)")
            .describe("wavelength bands measured besides the total"));
    s.params.push_back(choice_param("side", "front", {"front", "back", "both"})
                           .describe("which face counts")
                           .in_editor("Face counted"));
    s.params.push_back(string_param("unit", "unit")
                           .as_written("string of letters")
                           .describe("the name of the scene's length unit, for labels")
                           .in_editor("Length unit"));
    return s;
}

}  // namespace

const ElementSpec& detector_spec() {
    static const ElementSpec spec = declare_detector();
    return spec;
}

const ElementSpec& disc_spec() {
    static const ElementSpec spec = declare_disc();
    return spec;
}

const ElementSpec& rectangle_spec() {
    static const ElementSpec spec = declare_rectangle();
    return spec;
}

}  // namespace lenslab
