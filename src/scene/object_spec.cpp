#include "scene/object_spec.h"

#include "geometry/implicit_solid.h"

namespace lenslab {

namespace {

ElementSpec declare_common() {
    ElementSpec s{"object", "an object", {}};
    s.params = {
        string_param("type", "").needed().describe("which kind of object"),
        nested_param(ParamKind::String, "name")
            .meaning_auto("its path, e.g. `\"objects[3]\"`")
            .describe("shown by lenslab trace")
            .in_editor("Name"),
        nested_param(ParamKind::Object, "material")
            .needed()
            .as_written("string or object")
            .describe("a name from materials, or an inline material"),
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
    return s;
}

ElementSpec declare_triangle() {
    ElementSpec s = shape_spec("triangle", "a triangle", true);
    s.params.push_back(nested_param(ParamKind::Array, "vertices")
                           .needed()
                           .as_written("array of 3 points")
                           .describe("the corners; they must not be collinear"));
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
    return s;
}

}  // namespace

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
    ElementSpec s{std::move(name), std::move(phrase), {}};
    for (const ParamSpec& p : object_common_spec().params) {
        if (takes_detector || p.key != "detector") s.params.push_back(p);
    }
    return s;
}

bool is_common_object_key(const std::string& key) {
    return object_common_spec().find(key) != nullptr;
}

}  // namespace lenslab
