#include "optimize/lens_design.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "analysis/system/optical_system.h"
#include "optics/glass.h"
#include "optics/glass_library.h"
#include "optimize/design_configurations.h"
#include "optimize/lens_design_spec.h"
#include "scene/json_reader.h"
#include "scene/scene_json.h"
#include "scene/spec_reader.h"
#include "util/format_number.h"

namespace lenslab {

namespace {

using ojson = nlohmann::ordered_json;

// A list of numbers at `key`, each checked by `check` (which returns why not, or "").
std::vector<double> ld_numbers(JsonObjectReader& reader, const std::string& key,
                               const std::function<std::string(double)>& check) {
    const nlohmann::json& list = reader.require(key);
    if (!list.is_array() || list.empty()) {
        throw SceneError(reader.child_path(key), "must be a non-empty array of numbers");
    }
    std::vector<double> values;
    for (size_t i = 0; i < list.size(); ++i) {
        const std::string path = reader.child_path(key) + "[" + std::to_string(i) + "]";
        const double v = JsonObjectReader::as_number(list[i], path);
        if (const std::string why = check(v); !why.empty()) throw SceneError(path, why);
        values.push_back(v);
    }
    return values;
}

// The scene file's JSON with its keys in the file's order (the optimised file keeps them).
ojson ld_read_ordered(const std::string& file) {
    read_scene_json_file(file);  // the reader's checks and messages: unreadable, syntax, size
    std::ifstream in(file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return ojson::parse(text.str());
}

}  // namespace

LensDesign lens_design_from_json(const nlohmann::json& root, const std::string& base_dir) {
    SpecReader reader(root, "", lens_design_spec());
    LensDesign d;
    const nlohmann::json& system = reader.require("system");
    if (system.is_string()) {
        const std::filesystem::path file = system.get<std::string>();
        d.system_file = (file.is_relative() && !base_dir.empty())
                            ? (std::filesystem::path(base_dir) / file).string()
                            : file.string();
        d.base_dir = std::filesystem::path(d.system_file).parent_path().string();
        try {
            d.scene = ld_read_ordered(d.system_file);
        } catch (const SceneError& e) {
            throw SceneError("system", e.what());
        }
    } else if (system.is_object()) {
        d.scene = ojson::parse(system.dump());  // key order: see load_lens_design
        d.base_dir = base_dir;
    } else {
        throw SceneError("system", "must be a scene file name or a scene object");
    }
    // The scene as the renderer and the bench read it: every error names its place in it.
    OpticalSystem start;
    try {
        const Scene scene =
            scene_from_json(nlohmann::json(d.scene), d.base_dir, {.require_camera = false});
        start = build_optical_system(scene);
    } catch (const SceneError& e) {
        throw SceneError(d.system_file.empty() ? "system." + e.path() : "system",
                         d.system_file.empty() ? e.reason() : e.what());
    }
    const int surfaces = static_cast<int>(start.surfaces.size());
    const int64_t stop = reader.whole("stop");
    if (stop > surfaces) {
        throw SceneError("stop", "must be between 1 and " + std::to_string(surfaces) +
                                     " (the system's surfaces), got " + std::to_string(stop));
    }
    d.stop = static_cast<int>(stop) - 1;
    if (const nlohmann::json* air = reader.find("stop_in_air")) {
        if (reader.has("stop"))
            throw SceneError("stop_in_air", "give stop or stop_in_air, not both");
        JsonObjectReader r(*air, "stop_in_air", {"lens", "distance"}, "a stop in air");
        LensDesign::AirStop s;
        s.lens = r.string("lens");
        s.object = find_design_lens(d.scene, s.lens, r.child_path("lens"));
        s.distance = r.positive("distance");
        d.stop_in_air = s;
    }
    if (reader.has("epd") && reader.has("f_number")) {
        throw SceneError("f_number", "give epd or f_number, not both");
    }
    if (!reader.has("epd") && !reader.has("f_number")) throw_missing_key(root, "", "epd");
    d.epd = reader.real("epd");
    d.f_number = reader.real("f_number");
    d.fields = ld_numbers(reader, "fields", [](double v) {
        return std::abs(v) < 90.0 ? "" : "not a field angle (between -90 and 90 degrees)";
    });
    d.wavelengths = reader.has("wavelengths")
                        ? ld_numbers(reader, "wavelengths",
                                     [](double v) { return v > 0 ? "" : "must be > 0 (nm)"; })
                        : std::vector<double>{kLineF, kLineD, kLineC};
    for (size_t i = 0; i < d.wavelengths.size(); ++i) {
        try {
            check_wavelength(start, d.wavelengths[i], "the wavelength");
        } catch (const SceneError& e) {  // the design's key, then the lens that refuses it
            throw SceneError("wavelengths[" + std::to_string(i) + "]",
                             e.reason() + " (system." + e.path() + ")");
        }
    }
    if (reader.has("weights")) {
        d.weights =
            ld_numbers(reader, "weights", [](double v) { return v >= 0 ? "" : "must be >= 0"; });
        if (d.weights.size() != d.wavelengths.size()) {
            throw SceneError("weights",
                             "one weight per wavelength: " + std::to_string(d.wavelengths.size()) +
                                 " wavelengths, " + std::to_string(d.weights.size()) + " weights");
        }
    }
    d.rings = static_cast<int>(reader.whole("rings"));
    d.ray_aiming = *ray_aiming_named(reader.text("ray_aiming"));
    d.iterations = static_cast<int>(reader.whole("iterations"));
    if (const nlohmann::json* image = reader.find("image_distance")) {
        if (image->is_string()) {
            reader.choice("image_distance", "paraxial", {"paraxial"});
        } else {
            d.image_distance = reader.number("image_distance");
        }
    }
    const nlohmann::json* configurations = reader.find("configurations");
    if (configurations) read_configurations(*configurations, d);
    // Both lists are lenslab optimize's (optimize_design refuses a design without operands);
    // lenslab tolerance reads a design without them.
    const nlohmann::json variables =
        reader.has("variables") ? reader.require("variables") : nlohmann::json::array();
    if (!variables.is_array()) throw SceneError("variables", "must be an array of variables");
    for (size_t i = 0; i < variables.size(); ++i) {
        const std::string path = "variables[" + std::to_string(i) + "]";
        nlohmann::json spec = variables[i];
        const int configuration = read_variable_configuration(spec, path, d);
        d.variables.push_back(read_design_variable(spec, path, d.scene));
        DesignVariable& v = d.variables.back();
        if (configuration >= 0) {
            v.configuration = configuration;
            v.configuration_name = d.configurations[size_t(configuration)].name;
        }
        check_configuration_variable(d, v);
        // The same number twice, or shared and of one configuration both.
        const auto shared_label = [](DesignVariable w) {
            w.configuration = -1;
            return variable_label(w);
        };
        for (size_t j = 0; j + 1 < d.variables.size(); ++j) {
            const DesignVariable& w = d.variables[j];
            const bool both =
                w.configuration == v.configuration || w.configuration < 0 || v.configuration < 0;
            if (both && shared_label(w) == shared_label(v)) {
                throw SceneError(path, "the same variable as variables[" + std::to_string(j) +
                                           "] (" + variable_label(w) + ")");
            }
        }
        if (v.kind == VariableKind::ImageDistance && !d.image_distance) {
            throw SceneError(path,
                             "an image_distance variable needs a starting image_distance "
                             "(a number, not the paraxial focus)");
        }
    }
    // A configuration's variable starts where the configuration puts it, a shared one where
    // the first does.
    std::vector<DesignState> starts;
    for (size_t k = 0; k < d.configurations.size(); ++k) {
        const LensDesign at = configuration_design(d, int(k));
        starts.push_back({at.scene, at.image_distance.value_or(0.0)});
    }
    if (starts.empty()) starts.push_back({d.scene, d.image_distance.value_or(0.0)});
    for (const DesignVariable& v : d.variables) {
        const double value = variable_value(starts[size_t(std::max(v.configuration, 0))], v);
        if (v.bounded() && (value < *v.min || value > *v.max)) {
            throw SceneError(v.path, "starts at " + format_number(value) +
                                         ", outside its bounds [" + format_number(*v.min) + ", " +
                                         format_number(*v.max) + "]");
        }
    }
    const nlohmann::json* operands_given = reader.find("operands");
    const nlohmann::json operands = operands_given ? *operands_given : nlohmann::json();
    if (operands_given && (!operands.is_array() || operands.empty())) {
        throw SceneError("operands", "must be a non-empty array of operands");
    }
    if (configurations) {
        read_configuration_operands(operands_given, *configurations, d);
    }
    for (size_t i = 0; operands_given && !configurations && i < operands.size(); ++i) {
        for (MeritOperand& op : read_merit_operands(
                 operands[i], "operands[" + std::to_string(i) + "]", d.scene, d.fields)) {
            d.operands.push_back(std::move(op));
        }
    }
    if (const nlohmann::json* choices = reader.find("glass_choices")) {
        if (!choices->is_array()) {
            throw SceneError("glass_choices", "must be an array of glass choices");
        }
        for (size_t i = 0; i < choices->size(); ++i) {
            d.glass_choices.push_back(read_glass_choice((*choices)[i],
                                                        "glass_choices[" + std::to_string(i) + "]",
                                                        d.scene, d.base_dir, d.wavelengths));
        }
    }
    d.glass_iterations = static_cast<int>(reader.whole("glass_iterations"));
    if (const nlohmann::json* block = reader.find("global_search")) {
        SpecReader g(*block, "global_search", global_search_spec());
        d.global_search.starts = static_cast<int>(g.whole("starts"));
        d.global_search.start_iterations = static_cast<int>(g.whole("start_iterations"));
        d.global_search.keep = static_cast<int>(g.whole("keep"));
        d.global_search.seed = static_cast<uint64_t>(g.whole("seed"));
    }
    if (const nlohmann::json* block = reader.find("glass_substitution")) {
        SpecReader g(*block, "glass_substitution", glass_substitution_spec());
        d.glass_substitution.enabled = true;
        d.glass_substitution.candidates = static_cast<int>(g.whole("candidates"));
        if (block->contains("makers")) {
            const nlohmann::json& makers = (*block)["makers"];
            const std::string at = "glass_substitution.makers";
            if (!makers.is_array() || makers.empty())
                throw SceneError(at, "must be a non-empty array of maker names");
            const std::vector<std::string>& known = glass_makers();
            for (size_t i = 0; i < makers.size(); ++i) {
                const std::string where = at + "[" + std::to_string(i) + "]";
                if (!makers[i].is_string()) throw SceneError(where, "must be a maker's name");
                const std::string name = makers[i].get<std::string>();
                if (std::find(known.begin(), known.end(), name) == known.end()) {
                    std::string list;
                    for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
                    throw SceneError(where, "unknown maker '" + name + "' (makers: " + list + ")");
                }
                d.glass_substitution.makers.push_back(name);
            }
        }
    }
    if (const nlohmann::json* block = reader.find("tolerances")) {
        SpecReader t(*block, "tolerances", tolerances_spec());
        d.tolerances.radius = t.real("radius");
        d.tolerances.thickness = t.real("thickness");
        d.tolerances.air_gap = t.real("air_gap");
        d.tolerances.decenter = t.real("decenter");
        d.tolerances.tilt = t.real("tilt");
        d.tolerances.index = t.real("index");
        d.tolerances.abbe = t.real("abbe");
        d.tolerances.trials = static_cast<int>(t.whole("trials"));
        d.tolerances.seed = static_cast<uint64_t>(t.whole("seed"));
        d.tolerances.refocus = t.flag("refocus");
        d.tolerances.criterion = t.text("criterion");
        d.tolerances.frequency = t.real("frequency");
        if (d.tolerances.criterion == "mtf" && !(d.tolerances.frequency > 0))
            throw SceneError("tolerances.frequency",
                             "the mtf criterion needs a frequency > 0 (cycles per unit length)");
    }
    return d;
}

LensDesign load_lens_design(const std::string& path) {
    const nlohmann::json root = read_scene_json_file(path);
    const std::string base_dir = std::filesystem::path(path).parent_path().string();
    try {
        LensDesign d = lens_design_from_json(root, base_dir);
        if (d.system_file.empty()) {
            // An inline system keeps the file's key order in the optimised file too.
            std::ifstream in(path, std::ios::binary);
            std::stringstream text;
            text << in.rdbuf();
            d.scene = ojson::parse(text.str())["system"];
        }
        return d;
    } catch (const SceneError& e) {
        throw SceneError(path + ": " + e.path(), e.reason());
    }
}

}  // namespace lenslab
