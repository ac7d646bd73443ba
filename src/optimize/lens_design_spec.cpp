#include "optimize/lens_design_spec.h"

#include <algorithm>
#include <nlohmann/json.hpp>

namespace lenslab {

namespace {

// The most iterations a design (or --iterations) may ask for.
constexpr int64_t kMostIterations = 100000;

ElementSpec declare_design() {
    ElementSpec s{"design", "a design", {}, {}};
    s.params = {
        string_param("description", "").describe("free text"),
        nested_param(ParamKind::Object, "system")
            .needed()
            .as_written("string or object")
            .describe("the lens system: a scene file (relative to the design file's folder) "
                      "or a scene written inline"),
        whole_param("stop", 1, 1, 1 << 20)
            .describe("the aperture stop: a surface counted from 1 along the light"),
        nested_param(ParamKind::Object, "stop_in_air")
            .as_written("object")
            .describe("instead of `stop`: a stop in the air {`lens`, `distance`} behind that "
                      "lens's back vertex, moving with it"),
        number_param("epd", 0).above(0).describe("entrance pupil diameter"),
        number_param("f_number", 0)
            .above(0)
            .describe("instead of epd: the entrance pupil diameter is EFL / f_number"),
        nested_param(ParamKind::Array, "fields")
            .needed()
            .as_written("array of angles")
            .describe("field angles in degrees, the object at infinity"),
        nested_param(ParamKind::Array, "wavelengths")
            .as_written("array of nm")
            .describe("the wavelengths in air (default: the F, d and C lines)"),
        nested_param(ParamKind::Array, "weights")
            .as_written("array of numbers >= 0")
            .describe("one per wavelength, for the polychromatic spots (default: all equal)"),
        whole_param("rings", 4, 1, 32).describe("rings of each spot's hexapolar grid"),
        choice_param("ray_aiming", "real", {"real", "paraxial"})
            .describe("the spots' and wavefronts' rays aimed through the real stop (found by "
                      "iteration), or through the paraxial entrance pupil"),
        whole_param("iterations", 100, 0, kMostIterations)
            .describe("the most iterations of the solver"),
        nested_param(ParamKind::Number, "image_distance")
            .as_written("number, or \"paraxial\"")
            .describe("the image plane's distance from the last vertex, or the paraxial "
                      "focus solved again at every step (the default)"),
        nested_param(ParamKind::Array, "variables")
            .describe("what may change (lenslab optimize; default: nothing)"),
        nested_param(ParamKind::Array, "glass_choices")
            .describe("glasses to choose among after the continuous optimisation"),
        whole_param("glass_iterations", 20, 0, kMostIterations)
            .describe("iterations of the brief re-optimisation with each glass tried"),
        nested_param(ParamKind::Array, "operands")
            .describe("the merit function (required by lenslab optimize)"),
        nested_param(ParamKind::Object, "tolerances")
            .as_written("object")
            .describe("the errors `lenslab tolerance` tries (below)"),
        nested_param(ParamKind::Object, "global_search")
            .as_written("object")
            .describe("start the solver from many points, not only the design's (below)"),
        nested_param(ParamKind::Object, "glass_substitution")
            .as_written("object")
            .describe("model glasses replaced by the nearest catalogue glasses after the "
                      "optimisation (below)"),
        nested_param(ParamKind::Array, "configurations")
            .as_written("array of objects")
            .describe("a multi-configuration design, e.g. a zoom's focal lengths (below)"),
    };
    return s;
}

ElementSpec declare_configuration() {
    ElementSpec s{"configuration", "a configuration", {}, {}};
    s.params = {
        nested_param(ParamKind::String, "name")
            .meaning_auto("its number, from 1")
            .describe("names it in the reports and in variables' `configuration`"),
        nested_param(ParamKind::Array, "fields")
            .meaning_auto("the design's")
            .describe("its field angles, degrees"),
        nested_param(ParamKind::Number, "image_distance")
            .meaning_auto("the design's")
            .describe("its image plane's distance from the last vertex"),
        nested_param(ParamKind::Object, "air_gaps")
            .meaning_auto("the scene's")
            .describe("lens name → the air gap after that lens in this configuration"),
        nested_param(ParamKind::Array, "operands")
            .meaning_auto("none")
            .describe("operands of this configuration alone, beside the design's"),
    };
    return s;
}

ElementSpec declare_tolerances() {
    const ToleranceSettings d;
    ElementSpec s{"tolerances", "the tolerances", {}, {}};
    s.params = {
        number_param("radius", d.radius)
            .at_least(0)
            .describe("± error of every curved face's radius (flat faces keep theirs)"),
        number_param("thickness", d.thickness)
            .at_least(0)
            .describe("± error of every lens's centre thickness"),
        number_param("air_gap", d.air_gap)
            .at_least(0)
            .describe("± error of every air gap between lenses"),
        number_param("decenter", d.decenter)
            .at_least(0)
            .describe("± decentre of every lens from its axis, in x and in y (each alone)"),
        number_param("tilt", d.tilt)
            .at_least(0)
            .in_unit("degrees")
            .describe("± tilt of every lens about its front vertex, about x and about y"),
        number_param("index", d.index)
            .at_least(0)
            .describe("± error of every catalogue glass's n_d (a melt's departure)"),
        number_param("abbe", d.abbe)
            .at_least(0)
            .in_unit("%")
            .describe("± error of every catalogue glass's V_d, in percent of it"),
        whole_param("trials", d.trials, 1, 1000000).describe("made lenses of the Monte Carlo"),
        whole_param("seed", int64_t(d.seed), 0, int64_t{1} << 53)
            .describe("the Monte Carlo's random numbers"),
        flag_param("refocus", d.refocus)
            .describe("the back focus as compensator: each made lens refocused for the best "
                      "criterion"),
        choice_param("criterion", d.criterion, {"rms_spot", "rms_wavefront", "mtf"})
            .describe("what a made lens is judged by: its polychromatic RMS spot or RMS "
                      "wavefront, root mean square over the fields, or its MTF at `frequency`, "
                      "the mean over the fields"),
        number_param("frequency", d.frequency)
            .at_least(0)
            .describe("mtf: the spatial frequency, cycles per unit length (required by it)"),
    };
    return s;
}

ElementSpec declare_global_search() {
    const GlobalSearchSettings d;
    ElementSpec s{"global_search", "the global search", {}, {}};
    s.params = {
        whole_param("starts", 32, 1, 100000)
            .describe("points the solver starts from, the design's own the first"),
        whole_param("start_iterations", d.start_iterations, 1, kMostIterations)
            .describe("iterations from each start"),
        whole_param("keep", d.keep, 1, 100000)
            .describe("the best starts then run for the design's whole `iterations`"),
        whole_param("seed", int64_t(d.seed), 0, int64_t{1} << 53)
            .describe("the rotation of the starts' Halton sequence"),
    };
    return s;
}

ElementSpec declare_glass_substitution() {
    const GlassSubstitutionSettings d;
    ElementSpec s{"glass_substitution", "the glass substitution", {}, {}};
    s.params = {
        nested_param(ParamKind::Array, "makers")
            .as_written("array of maker names")
            .meaning_auto("every maker")
            .describe("the catalogues to choose from: SCHOTT, OHARA, CDGM, HOYA, HIKARI, SUMITA"),
        whole_param("candidates", d.candidates, 1, 1000)
            .describe("the glasses nearest each model glass on the glass map that are tried, "
                      "each re-optimised for `glass_iterations`"),
    };
    return s;
}

}  // namespace

const ElementSpec& glass_substitution_spec() {
    static const ElementSpec spec = declare_glass_substitution();
    return spec;
}

const ElementSpec& global_search_spec() {
    static const ElementSpec spec = declare_global_search();
    return spec;
}

const ElementSpec& lens_design_spec() {
    static const ElementSpec spec = declare_design();
    return spec;
}

const ElementSpec& configuration_spec() {
    static const ElementSpec spec = declare_configuration();
    return spec;
}

const ElementSpec& tolerances_spec() {
    static const ElementSpec spec = declare_tolerances();
    return spec;
}

const std::vector<DesignEntryType<VariableKind>>& variable_types() {
    static const std::vector<DesignEntryType<VariableKind>> types = {
        {"curvature", VariableKind::Curvature, {"lens", "surface", "min", "max"}},
        {"conic", VariableKind::Conic, {"lens", "surface", "min", "max"}},
        {"aspheric", VariableKind::Aspheric, {"lens", "surface", "order", "min", "max"}},
        {"thickness", VariableKind::Thickness, {"lens", "min", "max"}},
        {"air_gap", VariableKind::AirGap, {"lens", "min", "max"}},
        {"image_distance", VariableKind::ImageDistance, {"min", "max"}},
        {"n_d", VariableKind::GlassIndex, {"lens", "min", "max"}},
        {"V_d", VariableKind::GlassAbbe, {"lens", "min", "max"}},
        {"decenter_x", VariableKind::DecenterX, {"lens", "min", "max"}},
        {"decenter_y", VariableKind::DecenterY, {"lens", "min", "max"}},
        {"tilt_x", VariableKind::TiltX, {"lens", "min", "max"}},
        {"tilt_y", VariableKind::TiltY, {"lens", "min", "max"}},
        {"delta_n_d", VariableKind::MeltIndex, {"lens", "min", "max"}},
        {"delta_V_d", VariableKind::MeltAbbe, {"lens", "min", "max"}},
    };
    return types;
}

const std::vector<DesignEntryType<OperandKind>>& operand_types() {
    static const std::vector<DesignEntryType<OperandKind>> types = {
        {"efl", OperandKind::Efl, {"target", "weight"}},
        {"bfl", OperandKind::Bfl, {"target", "weight"}},
        {"entrance_pupil_position", OperandKind::EntrancePupilPosition, {"target", "weight"}},
        {"exit_pupil_position", OperandKind::ExitPupilPosition, {"target", "weight"}},
        {"distortion", OperandKind::Distortion, {"field", "target", "weight"}},
        {"rms_spot", OperandKind::RmsSpot, {"field", "target", "weight"}},
        {"real_ray_x", OperandKind::RealRayX, {"field", "px", "py", "target", "weight"}},
        {"real_ray_y", OperandKind::RealRayY, {"field", "px", "py", "target", "weight"}},
        {"rms_wavefront", OperandKind::RmsWavefront, {"field", "target", "weight"}},
        {"mtf", OperandKind::Mtf, {"frequency", "direction", "field", "target", "weight"}},
        {"min_center_thickness", OperandKind::MinCenterThickness, {"lens", "limit", "weight"}},
        {"max_center_thickness", OperandKind::MaxCenterThickness, {"lens", "limit", "weight"}},
        {"min_edge_thickness", OperandKind::MinEdgeThickness, {"lens", "limit", "weight"}},
        {"max_total_length", OperandKind::MaxTotalLength, {"limit", "weight"}},
        {"glass_distance", OperandKind::GlassDistance, {"lens", "limit", "weight"}},
    };
    return types;
}

template <class Kind>
std::vector<std::string> entry_keys(const std::vector<DesignEntryType<Kind>>& types) {
    std::vector<std::string> keys = {"type"};
    for (const DesignEntryType<Kind>& t : types) {
        for (const std::string& k : t.keys) {
            if (std::find(keys.begin(), keys.end(), k) == keys.end()) keys.push_back(k);
        }
    }
    return keys;
}

template <class Kind>
const DesignEntryType<Kind>& read_entry_type(const nlohmann::json& entry, JsonObjectReader& reader,
                                             const std::vector<DesignEntryType<Kind>>& types,
                                             const std::string& noun) {
    std::vector<std::string> names;
    for (const DesignEntryType<Kind>& t : types) names.push_back(t.type);
    if (!reader.has("type")) throw_missing_key(entry, reader.path(), "type");
    const std::string name = reader.choice("type", "", names);
    const auto type = std::find_if(types.begin(), types.end(),
                                   [&](const DesignEntryType<Kind>& t) { return t.type == name; });
    for (const auto& item : entry.items()) {
        const std::string& key = item.key();
        if (key == "type" || std::count(type->keys.begin(), type->keys.end(), key)) continue;
        std::string takes;
        for (const std::string& k : type->keys) takes += (takes.empty() ? "" : ", ") + k;
        // "an" before a vowel, and before rms and mtf as they are read (ar-em-es, em-tee-ef).
        const bool an = std::string("aeiou").find(name[0]) != std::string::npos ||
                        name.rfind("rms", 0) == 0 || name.rfind("mtf", 0) == 0;
        throw SceneError(reader.child_path(key),
                         (an ? "an " : "a ") + name + " " + noun + " takes no " + key +
                             " (it takes " +
                             (takes.empty() ? std::string("nothing but its type") : takes) + ")");
    }
    return *type;
}

template std::vector<std::string> entry_keys(const std::vector<DesignEntryType<VariableKind>>&);
template std::vector<std::string> entry_keys(const std::vector<DesignEntryType<OperandKind>>&);
template const DesignEntryType<VariableKind>& read_entry_type(
    const nlohmann::json&, JsonObjectReader&, const std::vector<DesignEntryType<VariableKind>>&,
    const std::string&);
template const DesignEntryType<OperandKind>& read_entry_type(
    const nlohmann::json&, JsonObjectReader&, const std::vector<DesignEntryType<OperandKind>>&,
    const std::string&);

}  // namespace lenslab
