#include "optimize/design_variable.h"

#include <algorithm>
#include <cmath>

#include "math/vec3.h"
#include "optimize/lens_design_spec.h"
#include "optimize/model_glass.h"
#include "scene/json_reader.h"
#include "util/format_number.h"

namespace lenslab {

namespace {

using ojson = nlohmann::ordered_json;

Vec3 dv_vec3(const ojson& v) {
    return Vec3(v.at(0).get<double>(), v.at(1).get<double>(), v.at(2).get<double>());
}

Vec3 dv_axis(const ojson& lens) {
    const auto it = lens.find("axis");
    return it == lens.end() ? Vec3(0, 0, 1) : normalize(dv_vec3(*it));
}

// Moves every lens whose centre lies behind lens `object` (along its axis) by `shift`.
void dv_move_lenses_behind(ojson& scene, int object, double shift) {
    ojson& objects = scene["objects"];
    const Vec3 axis = dv_axis(objects[object]);
    const Vec3 centre = dv_vec3(objects[object]["center"]);
    for (ojson& o : objects) {
        if (o.value("type", "") != "lens" || !o.contains("center")) continue;
        const Vec3 c = dv_vec3(o["center"]);
        if (dot(c - centre, axis) <= 1e-9) continue;
        const Vec3 moved = c + axis * shift;
        o["center"] = ojson::array({moved.x, moved.y, moved.z});
    }
}

// The next lens behind `object` along its axis (nearest centre), or -1.
int dv_next_lens(const ojson& scene, int object) {
    const ojson& objects = scene["objects"];
    const Vec3 axis = dv_axis(objects[object]);
    const Vec3 centre = dv_vec3(objects[object]["center"]);
    int next = -1;
    double nearest = INFINITY;
    for (int i = 0; i < static_cast<int>(objects.size()); ++i) {
        const ojson& o = objects[i];
        if (o.value("type", "") != "lens" || !o.contains("center") || !o.contains("thickness")) {
            continue;
        }
        const double s = dot(dv_vec3(o["center"]) - centre, axis);
        if (s > 1e-9 && s < nearest) {
            nearest = s;
            next = i;
        }
    }
    return next;
}

double dv_air_gap(const ojson& scene, int object) {
    const ojson& objects = scene["objects"];
    const ojson& lens = objects[object];
    const ojson& next = objects[dv_next_lens(scene, object)];
    const double s = dot(dv_vec3(next["center"]) - dv_vec3(lens["center"]), dv_axis(lens));
    return s - 0.5 * lens["thickness"].get<double>() - 0.5 * next["thickness"].get<double>();
}

// A radius standing for a flat conic or asphere, whose `radius` may not be 0.
constexpr double kFlatRadius = 1e12;

const char* dv_kind_name(VariableKind kind) {
    switch (kind) {
        case VariableKind::Curvature:
            return "curvature";
        case VariableKind::Conic:
            return "conic";
        case VariableKind::Aspheric:
            return "aspheric";
        case VariableKind::Thickness:
            return "thickness";
        case VariableKind::AirGap:
            return "air_gap";
        case VariableKind::ImageDistance:
            return "image_distance";
        case VariableKind::GlassIndex:
            return "n_d";
        case VariableKind::GlassAbbe:
            return "V_d";
        case VariableKind::DecenterX:
            return "decenter_x";
        case VariableKind::DecenterY:
            return "decenter_y";
        case VariableKind::TiltX:
            return "tilt_x";
        case VariableKind::TiltY:
            return "tilt_y";
        case VariableKind::MeltIndex:
            return "delta_n_d";
        case VariableKind::MeltAbbe:
            return "delta_V_d";
    }
    return "";
}

// The lens's material written inline (a named material copied in, so that changing a melt
// changes this lens's alone).
ojson& dv_inline_material(ojson& scene, ojson& lens) {
    ojson& m = lens["material"];
    if (m.is_string()) m = scene["materials"][m.get<std::string>()];
    return m;
}

}  // namespace

std::string variable_label(const DesignVariable& v) {
    std::string label = dv_kind_name(v.kind);
    if (v.kind != VariableKind::ImageDistance) label += " " + v.lens;
    if (!v.surface.empty()) label += "." + v.surface;
    if (v.kind == VariableKind::Aspheric) label += " A" + std::to_string(v.order);
    if (v.configuration >= 0) label += " [" + v.configuration_name + "]";
    return label;
}

double variable_value(const DesignState& state, const DesignVariable& v) {
    if (v.kind == VariableKind::ImageDistance) return state.image_distance;
    const ojson& lens = state.scene["objects"][v.object];
    switch (v.kind) {
        case VariableKind::Thickness:
            return lens["thickness"].get<double>();
        case VariableKind::AirGap:
            return dv_air_gap(state.scene, v.object);
        case VariableKind::GlassIndex:
            return lens["material"]["ior"]["n_d"].get<double>();
        case VariableKind::GlassAbbe:
            return lens["material"]["ior"]["V_d"].get<double>();
        case VariableKind::MeltIndex:
        case VariableKind::MeltAbbe:
            return lens_material(state.scene, v.object)->value(dv_kind_name(v.kind), 0.0);
        default:
            if (v.of_pose()) return lens.value(dv_kind_name(v.kind), 0.0);
            break;
    }
    const ojson& face = lens[v.surface];
    const std::string shape = face["shape"].get<std::string>();
    if (v.kind == VariableKind::Curvature) {
        return shape == "flat" ? 0.0 : 1.0 / face["radius"].get<double>();
    }
    if (v.kind == VariableKind::Conic) return face.value("k", 0.0);
    const size_t index = static_cast<size_t>((v.order - 4) / 2);
    const ojson& coefficients = face["coefficients"];
    return index < coefficients.size() ? coefficients[index].get<double>() : 0.0;
}

void set_variable(DesignState& state, const DesignVariable& v, double value) {
    if (v.kind == VariableKind::ImageDistance) {
        state.image_distance = value;
        return;
    }
    ojson& lens = state.scene["objects"][v.object];
    if (v.kind == VariableKind::Thickness) {
        const double change = value - lens["thickness"].get<double>();
        dv_move_lenses_behind(state.scene, v.object, change);
        // The front vertex stays: the centre moves by half the change.
        const Vec3 centre = dv_vec3(lens["center"]) + dv_axis(lens) * (0.5 * change);
        lens["center"] = ojson::array({centre.x, centre.y, centre.z});
        lens["thickness"] = value;
        return;
    }
    if (v.kind == VariableKind::AirGap) {
        dv_move_lenses_behind(state.scene, v.object, value - dv_air_gap(state.scene, v.object));
        return;
    }
    if (v.of_glass()) {
        lens["material"]["ior"][v.kind == VariableKind::GlassIndex ? "n_d" : "V_d"] = value;
        return;
    }
    if (v.of_melt()) {
        dv_inline_material(state.scene, lens)[dv_kind_name(v.kind)] = value;
        return;
    }
    if (v.of_pose()) {
        lens[dv_kind_name(v.kind)] = value;
        return;
    }
    ojson& face = lens[v.surface];
    const std::string shape = face["shape"].get<std::string>();
    if (v.kind == VariableKind::Curvature) {
        if (value == 0.0 && (shape == "sphere" || shape == "flat")) {
            face = ojson{{"shape", "flat"}};
        } else if (shape == "flat") {
            face = ojson{{"shape", "sphere"}, {"radius", 1.0 / value}};
        } else {
            face["radius"] = value == 0.0 ? kFlatRadius : 1.0 / value;
        }
    } else if (v.kind == VariableKind::Conic) {
        if (shape == "sphere") face["shape"] = "conic";
        face["k"] = value;
    } else {
        ojson& coefficients = face["coefficients"];
        const size_t index = static_cast<size_t>((v.order - 4) / 2);
        while (coefficients.size() <= index) coefficients.push_back(0.0);
        coefficients[index] = value;
    }
}

double variable_step(const DesignVariable& v) {
    constexpr double kSag = 1e-5;
    const double r = v.semi_diameter > 0 ? v.semi_diameter : 1.0;
    switch (v.kind) {
        case VariableKind::Curvature:
            return 2 * kSag / (r * r);  // sag ≈ c r² / 2
        case VariableKind::Aspheric:
            return kSag / std::pow(r, v.order);
        case VariableKind::Conic:
            return 1e-4;
        case VariableKind::GlassAbbe:
        case VariableKind::MeltAbbe:
            return 1e-3;  // V_d is tens: n_F - n_C = (n_d - 1) / V_d changes by about 1e-7
        case VariableKind::TiltX:
        case VariableKind::TiltY:
            return kSag / r * (180 / M_PI);  // degrees moving the rim by about kSag
        default:
            return kSag;
    }
}

const ojson* lens_material(const ojson& scene, int object) {
    const ojson& lens = scene["objects"][object];
    const auto m = lens.find("material");
    if (m == lens.end()) return nullptr;
    if (!m->is_string()) return &*m;
    const auto named = scene.find("materials");
    if (named == scene.end() || !named->contains(m->get<std::string>())) return nullptr;
    return &(*named)[m->get<std::string>()];
}

std::vector<DesignLens> design_lenses(const ojson& scene) {
    std::vector<DesignLens> lenses;
    const auto objects = scene.find("objects");
    if (objects == scene.end() || !objects->is_array()) return lenses;
    for (int i = 0; i < static_cast<int>(objects->size()); ++i) {
        const ojson& o = (*objects)[i];
        if (!o.is_object() || o.value("type", "") != "lens" || !o.contains("thickness")) continue;
        const std::string index = "objects[" + std::to_string(i) + "]";
        lenses.push_back({i, o.contains("name") && o["name"].is_string()
                                 ? o["name"].get<std::string>()
                                 : index});
    }
    return lenses;
}

int find_design_lens(const ojson& scene, const std::string& name, const std::string& path) {
    std::string known;
    for (const DesignLens& lens : design_lenses(scene)) {
        known += (known.empty() ? "" : ", ") + lens.name;
        if (lens.name == name || "objects[" + std::to_string(lens.object) + "]" == name) {
            return lens.object;
        }
    }
    throw SceneError(path, "no prescription lens named '" + name + "' in the system" +
                               (known.empty() ? " (it has none)" : " (lenses: " + known + ")"));
}

DesignVariable read_design_variable(const nlohmann::json& spec, const std::string& path,
                                    const ojson& scene) {
    JsonObjectReader reader(spec, path, entry_keys(variable_types()), "a variable");
    const DesignEntryType<VariableKind>& type =
        read_entry_type(spec, reader, variable_types(), "variable");
    DesignVariable v;
    v.path = path;
    v.kind = type.kind;
    if (reader.has("min") || reader.has("max")) {
        if (!reader.has("min")) throw_missing_key(spec, path, "min");
        if (!reader.has("max")) throw_missing_key(spec, path, "max");
        v.min = reader.number("min");
        v.max = reader.number("max");
        if (!(*v.min < *v.max)) {
            throw SceneError(
                reader.child_path("max"),
                "must be above min (" + format_number(*v.min) + "), got " + format_number(*v.max));
        }
    }
    if (v.kind == VariableKind::ImageDistance) return v;  // no lens
    const bool needs_surface = std::count(type.keys.begin(), type.keys.end(), "surface") > 0;
    v.lens = reader.string("lens");
    v.object = find_design_lens(scene, v.lens, reader.child_path("lens"));
    const ojson& lens = scene["objects"][v.object];
    if (lens.contains("diameter") && lens["diameter"].is_number()) {
        v.semi_diameter = 0.5 * lens["diameter"].get<double>();
    }
    if (!lens.contains("center")) {
        throw SceneError(reader.child_path("lens"), "the lens '" + v.lens + "' has no center");
    }
    if (v.kind == VariableKind::AirGap && dv_next_lens(scene, v.object) < 0) {
        throw SceneError(reader.child_path("lens"),
                         "no lens behind '" + v.lens +
                             "', so no air gap after it (the image_distance variable moves the "
                             "image plane)");
    }
    if (v.of_glass()) {
        if (!is_model_glass(lens)) {
            throw SceneError(reader.child_path("lens"),
                             "the lens '" + v.lens +
                                 "' needs its material written inline with an \"ior\" of "
                                 "{\"model\": \"abbe\", \"n_d\": ..., \"V_d\": ...} for its "
                                 "n_d and V_d to vary");
        }
        // Unbounded, a model glass would drift off the glass map: by default it keeps within
        // the catalogues' range of n_d or V_d.
        if (!v.bounded()) {
            const GlassMapRange range = catalogue_glass_range();
            v.min = v.kind == VariableKind::GlassIndex ? range.n_d_min : range.v_d_min;
            v.max = v.kind == VariableKind::GlassIndex ? range.n_d_max : range.v_d_max;
        }
        return v;
    }
    if (v.of_melt()) {
        const ojson* m = lens_material(scene, v.object);
        if (!m || !m->contains("glass")) {
            throw SceneError(reader.child_path("lens"),
                             "the lens '" + v.lens + "' needs a catalogue `glass` for a melt");
        }
    }
    if (!needs_surface) return v;
    if (!reader.has("surface")) throw_missing_key(spec, path, "surface");
    v.surface = reader.choice("surface", "", {"front", "back"});
    const ojson& face = lens[v.surface];
    const std::string shape = face.value("shape", "");
    const std::string where = "'" + v.lens + "' " + v.surface + " is a " + shape + " surface";
    if (shape == "sag") {
        throw SceneError(reader.child_path("surface"), where +
                                                           ": only sphere, flat, conic and "
                                                           "asphere faces have variables");
    }
    if (v.kind == VariableKind::Conic && shape == "flat") {
        throw SceneError(reader.child_path("surface"),
                         where + ", which has no conic constant (give it a radius first)");
    }
    if (v.kind == VariableKind::Aspheric) {
        if (shape != "asphere") {
            throw SceneError(reader.child_path("surface"),
                             where + ": aspheric coefficients need an asphere surface");
        }
        v.order = static_cast<int>(reader.integer("order", 4, 4, 16));
        if (v.order % 2 != 0) {
            throw SceneError(reader.child_path("order"),
                             "must be an even power of r, 4 to 16, got " + std::to_string(v.order));
        }
    }
    return v;
}

}  // namespace lenslab
