#include "optimize/design_configurations.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "optimize/lens_design_spec.h"
#include "scene/json_reader.h"
#include "scene/spec_reader.h"
#include "util/format_number.h"

namespace lenslab {

namespace {

std::string dc_path(size_t k) { return "configurations[" + std::to_string(k) + "]"; }

}  // namespace

void read_configurations(const nlohmann::json& list, LensDesign& d) {
    if (!list.is_array() || list.size() < 2) {
        throw SceneError("configurations",
                         "must be an array of at least two configurations (one is the design)");
    }
    for (size_t k = 0; k < list.size(); ++k) {
        const std::string path = dc_path(k);
        SpecReader r(list[k], path, configuration_spec());
        DesignConfiguration c;
        c.name = r.string("name", std::to_string(k + 1));
        // It names the configuration's optimised scene file too (zoom.tele.json).
        const bool plain =
            !c.name.empty() && std::all_of(c.name.begin(), c.name.end(), [](char ch) {
                return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-';
            });
        if (!plain)
            throw SceneError(r.child_path("name"),
                             "must be letters, digits, _ and -, got '" + c.name + "'");
        for (const DesignConfiguration& other : d.configurations) {
            if (other.name == c.name)
                throw SceneError(r.child_path("name"),
                                 "another configuration is named '" + c.name + "'");
        }
        c.fields = d.fields;
        if (const nlohmann::json* fields = r.find("fields")) {
            if (!fields->is_array() || fields->empty())
                throw SceneError(r.child_path("fields"), "must be a non-empty array of angles");
            c.fields.clear();
            for (size_t i = 0; i < fields->size(); ++i) {
                const std::string at = r.child_path("fields") + "[" + std::to_string(i) + "]";
                const double v = JsonObjectReader::as_number((*fields)[i], at);
                if (!(std::abs(v) < 90.0))
                    throw SceneError(at, "not a field angle (between -90 and 90 degrees)");
                c.fields.push_back(v);
            }
        }
        if (r.has("image_distance")) {
            if (!d.image_distance) {
                throw SceneError(r.child_path("image_distance"),
                                 "the design's image plane is the paraxial focus: give the "
                                 "design an image_distance first");
            }
            c.image_distance = r.real("image_distance");
        }
        if (const nlohmann::json* gaps = r.find("air_gaps")) {
            if (!gaps->is_object())
                throw SceneError(r.child_path("air_gaps"),
                                 "must map lens names to the air gap after each");
            for (const auto& [lens, value] : gaps->items()) {
                const std::string at = r.child_path("air_gaps") + "." + lens;
                DesignVariable gap;
                try {
                    gap = read_design_variable(nlohmann::json{{"type", "air_gap"}, {"lens", lens}},
                                               at, d.scene);
                } catch (const SceneError& e) {  // the key is the lens's name
                    throw SceneError(at, e.reason());
                }
                const double v = JsonObjectReader::as_number(value, at);
                if (!(v >= 0)) throw SceneError(at, "must be >= 0, got " + format_number(v));
                c.air_gaps.emplace_back(gap, v);
            }
        }
        d.configurations.push_back(std::move(c));
    }
}

int read_variable_configuration(nlohmann::json& spec, const std::string& path,
                                const LensDesign& d) {
    if (!spec.is_object() || !spec.contains("configuration")) return -1;
    const nlohmann::json given = spec["configuration"];
    spec.erase("configuration");
    const std::string at = path + ".configuration";
    if (d.configurations.empty()) throw SceneError(at, "the design has no configurations");
    for (size_t k = 0; k < d.configurations.size(); ++k) {
        if (given.is_string() && given.get<std::string>() == d.configurations[k].name)
            return int(k);
    }
    if (given.is_number_integer() && given.get<int64_t>() >= 1 &&
        given.get<int64_t>() <= int64_t(d.configurations.size()))
        return int(given.get<int64_t>() - 1);
    throw SceneError(at, "must name a configuration, or number it from 1 to " +
                             std::to_string(d.configurations.size()));
}

void check_configuration_variable(const LensDesign& d, const DesignVariable& v) {
    if (v.configuration >= 0) return;
    for (const DesignConfiguration& c : d.configurations) {
        bool sets = v.kind == VariableKind::ImageDistance && c.image_distance.has_value();
        for (const auto& [gap, value] : c.air_gaps) {
            sets = sets || (v.kind == VariableKind::AirGap && gap.object == v.object);
        }
        if (sets) {
            throw SceneError(v.path,
                             "configuration '" + c.name + "' sets this " +
                                 (v.kind == VariableKind::AirGap ? "air gap" : "image distance") +
                                 ": give the variable a configuration");
        }
    }
}

void read_configuration_operands(const nlohmann::json* shared, const nlohmann::json& list,
                                 LensDesign& d) {
    d.operands.clear();
    for (size_t k = 0; k < d.configurations.size(); ++k) {
        const DesignConfiguration& c = d.configurations[k];
        const auto add = [&](const nlohmann::json& spec, const std::string& path) {
            for (MeritOperand& op : read_merit_operands(spec, path, d.scene, c.fields)) {
                op.configuration = int(k);
                op.configuration_name = c.name;
                d.operands.push_back(std::move(op));
            }
        };
        for (size_t i = 0; shared && i < shared->size(); ++i) {
            add((*shared)[i], "operands[" + std::to_string(i) + "]");
        }
        const auto own = list[k].find("operands");
        if (own == list[k].end()) continue;
        if (!own->is_array())
            throw SceneError(dc_path(k) + ".operands", "must be an array of operands");
        for (size_t i = 0; i < own->size(); ++i) {
            add((*own)[i], dc_path(k) + ".operands[" + std::to_string(i) + "]");
        }
    }
    if (d.operands.empty()) {
        throw SceneError("operands", "must be a non-empty array of operands");
    }
}

LensDesign configuration_design(const LensDesign& d, int k, std::vector<int>* globals) {
    const DesignConfiguration& c = d.configurations[size_t(k)];
    LensDesign one = d;
    one.configurations.clear();
    DesignState state{d.scene, d.image_distance.value_or(0.0)};
    for (const auto& [gap, value] : c.air_gaps) set_variable(state, gap, value);
    one.scene = state.scene;
    one.fields = c.fields;
    if (c.image_distance) one.image_distance = c.image_distance;
    one.variables.clear();
    if (globals) globals->clear();
    for (size_t i = 0; i < d.variables.size(); ++i) {
        if (d.variables[i].configuration != -1 && d.variables[i].configuration != k) continue;
        one.variables.push_back(d.variables[i]);
        if (globals) globals->push_back(int(i));
    }
    one.operands.clear();
    for (const MeritOperand& op : d.operands) {
        if (op.configuration == k) one.operands.push_back(op);
    }
    return one;
}

}  // namespace lenslab
