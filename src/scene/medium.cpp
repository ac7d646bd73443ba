#include "scene/medium.h"

#include <cmath>
#include <nlohmann/json.hpp>

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
        string_param("density", "")
            .as_written("formula f(x, y, z), or a grid object")
            .describe("multiplies both coefficients at each point (x, y, z in scene units); "
                      "\"\": the same everywhere")
            .in_editor("Density f(x, y, z)"),
        number_param("density_max", 0)
            .above(0)
            .meaning_auto("auto: a grid's largest value; 1.25 times the largest f on a 33 x 33 "
                          "x 33 grid over the medium's box")
            // Not in the editor: its automatic estimate suits a form, and 0 is no bound.
            .describe("a bound f never exceeds, for delta and ratio tracking"),
    };
    s.example = nlohmann::json::parse(R"json({"scattering": 0.05, "g": 0.3})json");
    return s;
}

}  // namespace

const ElementSpec& medium_spec() {
    static const ElementSpec spec = declare_medium();
    return spec;
}

namespace {

// The density at `path` (a formula or a grid), with its majorant over `region`: the user's,
// checked against the density's values, or estimated from them.
std::shared_ptr<const MediumDensity> read_density(SpecReader& r, const Aabb& region,
                                                  double user_bound) {
    const std::string path = r.child_path("density");
    std::shared_ptr<MediumDensity> d;
    if (r.require("density").is_object()) {
        d = std::make_shared<MediumDensity>(read_density_grid(r.require("density"), path), path);
    } else {
        try {
            d = std::make_shared<MediumDensity>(r.text("density"), path);
        } catch (const FormulaError& e) {
            throw SceneError(path, e.message());
        }
    }
    const MediumDensity::Survey s = d->survey(region);
    if (!s.problem.empty()) throw SceneError(path, s.problem);
    double bound = s.exact ? s.max : s.max * MediumDensity::kSafety;
    if (user_bound > 0) {
        bound = user_bound;
        if (s.max > bound) {
            throw SceneError(r.child_path("density_max"), "is below the density, which reaches " +
                                                              format_number(s.max) +
                                                              " inside the medium's box");
        }
    }
    d->bound_over(region, bound);
    return d;
}

}  // namespace

Medium read_medium(const nlohmann::json& j, const std::string& path, const Aabb& region) {
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
    const double user_bound = r.has("density_max") ? r.real("density_max") : 0;
    const nlohmann::json* density = r.find("density");
    if (density && (density->is_object() || !r.text("density").empty())) {
        m.density = read_density(r, region, user_bound);
    } else if (user_bound > 0) {
        throw SceneError(r.child_path("density_max"), "bounds a density: give one too");
    }
    return m;
}

std::optional<Medium> read_atmosphere(const nlohmann::json& j, const Aabb& region) {
    Medium m = read_medium(j, "atmosphere", region);
    if (m.is_clear() || (m.density && m.density->bound() == 0)) return std::nullopt;
    return m;
}

bool atmosphere_needs_region(const nlohmann::json& j) {
    return j.is_object() && j.contains("density");
}

}  // namespace lenslab
