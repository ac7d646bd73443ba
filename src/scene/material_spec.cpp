#include "scene/material_spec.h"

#include "scene/material.h"

namespace lenslab {

namespace {

ElementSpec declare_material() {
    const Material d;
    ElementSpec s{"material", "a material", {}, {}};
    s.params = {
        albedo_param("color", d.color)
            .describe("diffuse (Lambertian) albedo")
            .in_editor("Colour (albedo)"),
        fraction_param("transparency", d.transparency)
            .describe("share of light that meets the dielectric interface")
            .in_editor("Transparency"),
        fraction_param("specular", d.specular)
            .describe("share reflected by a perfect mirror")
            .in_editor("Specular (mirror)"),
        // A number here; an object is a dispersion model (spectral_json.h).
        number_param("ior", d.ior(kLineD))
            .above(0)
            .as_written("number, or a dispersion model")
            .describe("refractive index of the inside (relative to the ambient medium), or a model")
            .in_editor("Refractive index"),
        nested_param(ParamKind::String, "glass").describe("a catalogue glass, e.g. N-BK7"),
        number_param("delta_n_d", 0.0)
            .describe("with `glass`: the melt's n_d minus the catalogue's (a melt sheet's value, "
                      "or a tolerance's)")
            .in_editor("Melt Δn_d"),
        number_param("delta_V_d", 0.0)
            .describe("with `glass`: the melt's V_d minus the catalogue's (the dispersion keeps "
                      "its shape)")
            .in_editor("Melt ΔV_d"),
        nested_param(ParamKind::Object, "emission").describe("light emitted by the surface"),
        nested_param(ParamKind::Object, "grin")
            .describe("a gradient index inside the solid (replaces ior; see docs/grin.md)"),
    };
    return s;
}

ElementSpec declare_grin() {
    ElementSpec s{"grin", "a GRIN index", {}, {}};
    ParamSpec radius = number_param("radius", 1.0)
                           .above(0)
                           .describe("R of the luneburg and fisheye profiles (required by them)")
                           .in_editor("Profile radius R");
    radius.fallback = nullptr;
    radius.auto_meaning = "—";
    s.params = {
        choice_param("profile", "luneburg", {"luneburg", "fisheye", "radial", "axial", "formula"})
            .needed()
            .describe("the index profile n(x, y, z)"),
        number_param("n0", 1.5)
            .above(0)
            .describe("index on the axis or at the centre (fisheye, radial, axial)")
            .in_editor("Index n0"),
        number_param("A", 0.0)
            .describe("radial: n0 (1 - A r^2/2), per unit^2; axial: n0 + A z, per unit")
            .in_editor("Gradient A"),
        radius,
        nested_param(ParamKind::String, "formula")
            .describe("the index as a formula of x, y, z (required by the formula profile)")
            .in_editor("Index n(x, y, z)"),
        nested_param(ParamKind::Point, "center")
            .meaning_auto("the object's centre")
            .describe("the profile's centre"),
        vector_param(ParamKind::Direction, "axis", nlohmann::json::array({0, 0, 1}))
            .describe("the profile's axis (radial, axial)")
            .in_editor("Profile axis"),
    };
    return s;
}

ElementSpec declare_emission() {
    const Material d;
    ElementSpec s{"emission", "an emission", {}, {}};
    s.params = {
        colour_param("color", d.emission_color)
            .describe("colour of the emitted light; 1 is D65 daylight white")
            .in_editor("Emission colour"),
        nested_param(ParamKind::Object, "spectrum")
            .as_written("spectrum")
            .describe("instead of color: a named spectrum"),
        // Giving an emission means it emits: intensity 1 unless said (Material's 0 is none).
        number_param("intensity", 1.0)
            .at_least(0)
            .describe("scale of the emitted radiance (W m^-2 sr^-1)")
            .in_editor("Emission intensity"),
    };
    return s;
}

}  // namespace

const ElementSpec& material_spec() {
    static const ElementSpec spec = declare_material();
    return spec;
}

const ElementSpec& grin_spec() {
    static const ElementSpec spec = declare_grin();
    return spec;
}

const ElementSpec& emission_spec() {
    static const ElementSpec spec = declare_emission();
    return spec;
}

std::vector<std::string> grin_keys_of(const std::string& profile) {
    if (profile == "luneburg") return {"radius"};
    if (profile == "fisheye") return {"n0", "radius"};
    if (profile == "radial" || profile == "axial") return {"n0", "A", "axis"};
    if (profile == "formula") return {"formula"};
    return {};
}

nlohmann::json grin_starting_block(const std::string& profile) {
    // Values that make a visible lens of a unit-sized object: a radial rod of pitch about 20,
    // an axial gradient of 0.05 per unit, a formula equal to crown glass.
    nlohmann::json block = {{"profile", profile}};
    if (profile == "luneburg") block["radius"] = 1.0;
    if (profile == "fisheye") block.update({{"n0", 2.0}, {"radius", 1.0}});
    if (profile == "radial") block.update({{"n0", 1.6}, {"A", 0.1}});
    if (profile == "axial") block.update({{"n0", 1.5}, {"A", 0.05}});
    if (profile == "formula") block["formula"] = "1.5 + 0.02 * z";
    return block;
}

}  // namespace lenslab
