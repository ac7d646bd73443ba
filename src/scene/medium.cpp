#include "scene/medium.h"

#include <cmath>

#include "scene/spec_reader.h"

namespace lenslab {

BandWeights Medium::transmittance(double d) const {
    const BandWeights s = extinction();
    return {std::exp(-s[0] * d), std::exp(-s[1] * d), std::exp(-s[2] * d)};
}

namespace {

ElementSpec declare_medium() {
    ElementSpec s{"medium", "a medium", {}, {}};
    s.params = {
        colour_param("absorption", Rgb{0, 0, 0})
            .as_written("number or [r, g, b]")
            .describe("absorption coefficient per scene unit")
            .in_editor("Absorption"),
        colour_param("scattering", Rgb{0, 0, 0})
            .as_written("number or [r, g, b]")
            .describe("scattering coefficient per scene unit")
            .in_editor("Scattering"),
        number_param("g", 0)
            .at_least(-1)
            .at_most(1)
            .describe("phase function's mean cosine: > 0 forward, 0 even, < 0 back")
            .in_editor("Anisotropy g"),
    };
    s.example = nlohmann::json::parse(R"json({"scattering": 0.05, "g": 0.3})json");
    return s;
}

}  // namespace

const ElementSpec& medium_spec() {
    static const ElementSpec spec = declare_medium();
    return spec;
}

Medium read_medium(const nlohmann::json& j, const std::string& path) {
    SpecReader r(j, path, medium_spec());
    Medium m;
    // A grey coefficient is the same number in every band, exactly: light of any colour
    // crosses the medium alike, and the tracers need not split it by wavelength.
    const auto bands = [](const Rgb& c) {
        return c.r == c.g && c.g == c.b ? BandWeights{c.r, c.r, c.r} : coefficient_bands(c);
    };
    m.absorption = bands(r.colour("absorption"));
    m.scattering = bands(r.colour("scattering"));
    m.g = r.real("g");
    return m;
}

std::optional<Medium> read_atmosphere(const nlohmann::json& j) {
    Medium m = read_medium(j, "atmosphere");
    if (m.is_clear()) return std::nullopt;
    return m;
}

}  // namespace lenslab
