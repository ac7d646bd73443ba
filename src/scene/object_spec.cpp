#include "scene/object_spec.h"

#include "geometry/implicit_solid.h"

namespace lenslab {

namespace {

ElementSpec declare_common() {
    ElementSpec s{"object", "an object", {}, {}};
    s.params = {
        string_param("type", "").needed().describe("which kind of object"),
        nested_param(ParamKind::String, "name")
            .meaning_auto("its path, e.g. `\"objects[3]\"`")
            .describe("shown by lenslab trace")
            .in_editor("Name"),
        nested_param(ParamKind::Object, "material")
            .meaning_auto("**required**, but for a shape with a `medium`")
            .as_written("string or object")
            .describe("a name from materials, or an inline material"),
        nested_param(ParamKind::Object, "medium")
            .as_written("object")
            .describe("closed shapes only: the participating medium inside"),
        nested_param(ParamKind::Object, "detector")
            .as_written("`true`, `false` or object")
            .describe("triangles, discs and rectangles only: measure the light arriving"),
        nested_param(ParamKind::Boolean, "photon_target")
            .meaning_auto("auto")
            .describe("aim caustic photons at it")
            .in_editor("Photon target (aim caustic photons)"),
    };
    return s;
}

ElementSpec declare_sphere() {
    ElementSpec s = shape_spec("sphere", "a sphere", false);
    s.params.push_back(point_param("center").describe("centre").in_editor("Centre"));
    s.params.push_back(
        number_param("radius", 0).above(0).needed().describe("radius").in_editor("Radius"));
    s.example = nlohmann::json::parse(
        R"json({"type": "sphere", "name": "sphere", "center": [0, 0, 0], "radius": 0.4, "material": {"color": 0.7}})json");
    return s;
}

ElementSpec declare_triangle() {
    ElementSpec s = shape_spec("triangle", "a triangle", true);
    s.params.push_back(nested_param(ParamKind::Array, "vertices")
                           .of_positions()
                           .needed()
                           .as_written("array of 3 points")
                           .describe("the corners; they must not be collinear"));
    s.example = nlohmann::json::parse(
        R"json({"type": "triangle", "name": "triangle", "vertices": [[-0.5, -0.5, 0], [0.5, -0.5, 0], [0, 0.5, 0]], "material": {"color": 0.7}})json");
    return s;
}

ElementSpec declare_implicit() {
    ElementSpec s = shape_spec("implicit", "an implicit", false);
    s.params.push_back(string_param("formula", "")
                           .needed()
                           .describe("f(x, y, z); the inside is where it is <= 0")
                           .in_editor("f(x, y, z) <= 0"));
    s.params.push_back(nested_param(ParamKind::Array, "bounds")
                           .needed()
                           .as_written("two points")
                           .describe("the box the solid is cut to"));
    s.params.push_back(vector_param(ParamKind::Point, "center", nlohmann::json::array({0, 0, 0}))
                           .describe("where the formula's origin lies in the scene")
                           .in_editor("Centre"));
    s.params.push_back(whole_param("steps", ImplicitSolid::kDefaultSteps, 8, 1 << 16)
                           .describe("the march's resolution")
                           .in_editor("March steps"));
    s.example = nlohmann::json::parse(
        R"json({"type": "implicit", "name": "torus", "center": [0, 0, 0], "formula": "(sqrt(x^2 + z^2) - 0.4)^2 + y^2 - 0.15^2", "bounds": [[-0.6, -0.2, -0.6], [0.6, 0.2, 0.6]], "material": {"color": 1, "transparency": 1, "ior": 1.5}})json");
    return s;
}

// One declaration for both forms; which form a key belongs to is in its doc line, and the
// rule that the forms do not mix stays with the reader (object_types.cpp).
ElementSpec declare_lens() {
    ElementSpec s = shape_spec("lens", "a lens", false);
    s.params.push_back(point_param("center")
                           .describe("the point on the optical axis midway between the vertices")
                           .in_editor("Centre"));
    s.params.push_back(direction_param("axis")
                           .describe("the optical axis, from the front vertex to the back vertex")
                           .in_editor("Axis"));
    const auto length = [](std::string key, std::string form, std::string doc, std::string label) {
        return nested_param(ParamKind::Number, std::move(key))
            .above(0)
            .meaning_auto("**required** in the " + form + " form")
            .describe(form + " form: " + doc)
            .in_editor(std::move(label));
    };
    s.params.push_back(
        length("curvature_radius", "report", "R, the radius of both spheres", "Curvature radius"));
    s.params.push_back(length("aperture_radius", "report",
                              "h, the distance from the axis to the edge; h <= R",
                              "Aperture radius"));
    s.params.push_back(length("thickness", "prescription",
                              "centre thickness, vertex to vertex along the axis",
                              "Centre thickness"));
    s.params.push_back(length("diameter", "prescription",
                              "diameter of the lens (twice the rim radius)", "Diameter"));
    for (const char* side : {"front", "back"}) {
        s.params.push_back(
            nested_param(ParamKind::Object, side)
                .meaning_auto("**required** in the prescription form")
                .as_written("surface")
                .describe(std::string("prescription form: the ") +
                          (side == std::string("front") ? "surface met first along axis"
                                                        : "other surface")));
    }
    s.params.push_back(nested_param(ParamKind::Direction, "x_axis")
                           .meaning_auto("a fixed perpendicular to `axis`")
                           .describe("prescription form: where the lens's local x axis points")
                           .in_editor("Local x axis"));
    add_decentring_params(s, "lens",
                          " (prescription form; the optical bench keeps the axis `center` and "
                          "`axis` give, as designed)");
    s.example = nlohmann::json::parse(
        R"json({"type": "lens", "name": "lens", "center": [0, 0, 0], "axis": [0, 0, 1], "thickness": 0.3, "diameter": 1, "front": {"shape": "sphere", "radius": 1.5}, "back": {"shape": "sphere", "radius": -1.5}, "material": {"color": 1, "transparency": 1, "ior": 1.5}})json");
    return s;
}

}  // namespace

const ElementSpec& lens_spec() {
    static const ElementSpec spec = declare_lens();
    return spec;
}

const ElementSpec& object_common_spec() {
    static const ElementSpec spec = declare_common();
    return spec;
}

const ElementSpec& sphere_spec() {
    static const ElementSpec spec = declare_sphere();
    return spec;
}

const ElementSpec& triangle_spec() {
    static const ElementSpec spec = declare_triangle();
    return spec;
}

const ElementSpec& implicit_spec() {
    static const ElementSpec spec = declare_implicit();
    return spec;
}

ElementSpec shape_spec(std::string name, std::string phrase, bool takes_detector) {
    ElementSpec s{std::move(name), std::move(phrase), {}, {}};
    for (const ParamSpec& p : object_common_spec().params) {
        if (takes_detector || p.key != "detector") s.params.push_back(p);
    }
    return s;
}

void add_decentring_params(ElementSpec& s, const std::string& what, const std::string& moved) {
    s.params.push_back(number_param("decenter_x", 0)
                           .describe("moves the " + what + " along the axis frame's x" + moved)
                           .in_editor("Decentre x"));
    s.params.push_back(number_param("decenter_y", 0)
                           .describe("moves the " + what + " along the axis frame's y" + moved)
                           .in_editor("Decentre y"));
    s.params.push_back(number_param("tilt_x", 0)
                           .above(-90)
                           .below(90)
                           .in_unit("degrees")
                           .describe("then turns it about x through its front vertex, +z towards "
                                     "-y (Zemax's coordinate break, order 0)")
                           .in_editor("Tilt about x (degrees)"));
    s.params.push_back(number_param("tilt_y", 0)
                           .above(-90)
                           .below(90)
                           .in_unit("degrees")
                           .describe("then about the turned y, +z towards +x")
                           .in_editor("Tilt about y (degrees)"));
    s.params.push_back(number_param("tilt_z", 0)
                           .above(-360)
                           .below(360)
                           .in_unit("degrees")
                           .describe("then about its own axis, +x towards +y")
                           .in_editor("Tilt about z (degrees)"));
}

bool is_common_object_key(const std::string& key) {
    return object_common_spec().find(key) != nullptr;
}

}  // namespace lenslab
