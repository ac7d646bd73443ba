#include "scene/light_spec.h"

#include "optics/spectrum.h"
#include "scene/light.h"

namespace lenslab {

std::vector<ParamSpec> light_emission_params(const Rgb& colour, std::string power_meaning) {
    return {
        number_param("power", 0)
            .above(0)
            .needed()
            .describe(std::move(power_meaning))
            .in_editor("Power (W)"),
        colour_param("color", colour)
            .describe("the light's colour; 1 is D65 daylight white")
            .in_editor("Colour"),
        nested_param(ParamKind::Object, "spectrum")
            .as_written("spectrum")
            .describe("instead of color: a named spectrum"),
    };
}

namespace {

// A beam's or a laser's shapes: a slit across it, or a line laser's fan (not both; the
// rules between fields are the reader's, light_json.cpp).
void add_beam_shapes(ElementSpec& s) {
    s.params.push_back(number_param("slit_width", 0)
                           .at_least(0)
                           .describe("width of a slit across the beam (at most 2 radius); 0: none")
                           .in_editor("Slit width"));
    s.params.push_back(
        vector_param(ParamKind::Direction, "slit_axis", nullptr)
            .meaning_auto(
                "`[0, 1, 0]` made square to `direction`, or `[0, 0, -1]` for a vertical beam")
            .describe("the slit's long side, across the beam (unused without slit_width)")
            .in_editor("Slit axis"));
    s.params.push_back(number_param("fan_angle", 0)
                           .at_least(0)
                           .below(180)
                           .in_unit("degrees")
                           .describe("full angle of a line laser's fan; 0: a plain beam")
                           .in_editor("Fan angle"));
    s.params.push_back(
        vector_param(ParamKind::Direction, "fan_axis", nullptr)
            .meaning_auto(
                "horizontal: square to `direction` and `[0, 1, 0]` (along *x* for a vertical beam)")
            .describe(
                "the direction across the beam the fan spreads along (unused without fan_angle)")
            .in_editor("Fan axis"));
}

ElementSpec declare_point() {
    ElementSpec s{"point light", "a point light", {}, {}};
    s.params = {
        string_param("type", "point").needed().describe("\"point\""),
        point_param("position").describe("where the light is").in_editor("Position"),
    };
    for (ParamSpec& p : light_emission_params(PointLight{}.color)) s.params.push_back(std::move(p));
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
    for (ParamSpec& p : light_emission_params(BeamLight{}.color)) s.params.push_back(std::move(p));
    add_beam_shapes(s);
    s.example = nlohmann::json::parse(
        R"json({"type": "beam", "origin": [0, 1, 0], "direction": [0, -1, 0], "radius": 0.3, "power": 10})json");
    return s;
}

ElementSpec declare_laser() {
    ElementSpec s{"laser", "a laser", {}, {}};
    s.params = {
        string_param("type", "laser").needed().describe("\"laser\""),
        point_param("position")
            .describe("centre of the beam's exit aperture")
            .in_editor("Position"),
        direction_param("direction").describe("where the beam goes").in_editor("Direction"),
        number_param("radius", 0)
            .above(0)
            .needed()
            .describe("radius of the beam")
            .in_editor("Beam radius"),
        number_param("power", 0)
            .above(0)
            .needed()
            .describe("radiant flux (W)")
            .in_editor("Power (W)"),
        number_param("wavelength", 532)
            .at_least(kLambdaMinNm)
            .at_most(kLambdaMaxNm)
            .in_unit("nm")
            .describe("the laser line (0.1 nm wide)")
            .in_editor("Wavelength (nm)"),
        nested_param(ParamKind::Object, "spectrum")
            .as_written("spectrum")
            .describe("instead of wavelength: any spectrum, as for a point light"),
    };
    add_beam_shapes(s);
    s.example = nlohmann::json::parse(
        R"json({"type": "laser", "position": [0, 1, 0], "direction": [1, 0, 0], "radius": 0.02, "power": 1, "wavelength": 532})json");
    return s;
}

ElementSpec declare_spot() {
    ElementSpec s{"spot light", "a spot light", {}, {}};
    s.params = {
        string_param("type", "spot").needed().describe("\"spot\""),
        point_param("position").describe("where the light is").in_editor("Position"),
        direction_param("direction").describe("the cone's axis").in_editor("Direction"),
        number_param("cone_angle", SpotLight{}.cone_angle)
            .above(0)
            .at_most(90)
            .in_unit("degrees")
            .describe("half-angle of the lit cone")
            .in_editor("Cone angle"),
        number_param("falloff", SpotLight{}.falloff)
            .at_least(0)
            .in_unit("degrees")
            .describe("width of the soft edge inside the cone (at most cone_angle)")
            .in_editor("Falloff"),
    };
    for (ParamSpec& p :
         light_emission_params(SpotLight{}.color, "radiant flux (W) sent into the cone"))
        s.params.push_back(std::move(p));
    s.example = nlohmann::json::parse(
        R"json({"type": "spot", "position": [0, 2, 0], "direction": [0, -1, 0], "cone_angle": 20, "power": 10})json");
    return s;
}

}  // namespace

const ElementSpec& laser_spec() {
    static const ElementSpec spec = declare_laser();
    return spec;
}

const ElementSpec& spot_light_spec() {
    static const ElementSpec spec = declare_spot();
    return spec;
}

const ElementSpec& point_light_spec() {
    static const ElementSpec spec = declare_point();
    return spec;
}

const ElementSpec& beam_spec() {
    static const ElementSpec spec = declare_beam();
    return spec;
}

}  // namespace lenslab
