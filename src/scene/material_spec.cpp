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
        nested_param(ParamKind::Object, "emission").describe("light emitted by the surface"),
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

const ElementSpec& emission_spec() {
    static const ElementSpec spec = declare_emission();
    return spec;
}

}  // namespace lenslab
