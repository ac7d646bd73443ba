#include "scene/light_spec.h"

#include "scene/light.h"

namespace lenslab {

namespace {

// What every light takes besides where it is.
std::vector<ParamSpec> emission_params(const Rgb& colour) {
    return {
        number_param("power", 0)
            .above(0)
            .needed()
            .describe("radiant flux (W)")
            .in_editor("Power (W)"),
        colour_param("color", colour)
            .describe("the light's colour; 1 is D65 daylight white")
            .in_editor("Colour"),
        nested_param(ParamKind::Object, "spectrum")
            .as_written("spectrum")
            .describe("instead of color: a named spectrum"),
    };
}

ElementSpec declare_point() {
    ElementSpec s{"point light", "a point light", {}, {}};
    s.params = {
        string_param("type", "point").needed().describe("\"point\""),
        point_param("position").describe("where the light is").in_editor("Position"),
    };
    for (ParamSpec& p : emission_params(PointLight{}.color)) s.params.push_back(std::move(p));
    s.example =
        nlohmann::json::parse(R"json({"type": "point", "position": [0, 1, 0], "power": 100})json");
    return s;
}

ElementSpec declare_beam() {
    ElementSpec s{"beam", "a beam", {}, {}};
    s.params = {
        string_param("type", "beam").needed().describe("\"beam\""),
        point_param("origin")
            .describe("centre of the disc the beam leaves from")
            .in_editor("Origin"),
        direction_param("direction").describe("where the beam goes").in_editor("Direction"),
        number_param("radius", 0)
            .above(0)
            .needed()
            .describe("radius of the beam's disc")
            .in_editor("Beam radius"),
    };
    for (ParamSpec& p : emission_params(BeamLight{}.color)) s.params.push_back(std::move(p));
    s.example = nlohmann::json::parse(
        R"json({"type": "beam", "origin": [0, 1, 0], "direction": [0, -1, 0], "radius": 0.3, "power": 10})json");
    return s;
}

}  // namespace

const ElementSpec& point_light_spec() {
    static const ElementSpec spec = declare_point();
    return spec;
}

const ElementSpec& beam_spec() {
    static const ElementSpec spec = declare_beam();
    return spec;
}

const std::vector<const ElementSpec*>& light_specs() {
    static const std::vector<const ElementSpec*> specs{&point_light_spec(), &beam_spec()};
    return specs;
}

const ElementSpec* find_light_spec(const std::string& type) {
    for (const ElementSpec* s : light_specs()) {
        if (s->example.value("type", "") == type) return s;
    }
    return nullptr;
}

}  // namespace lenslab
