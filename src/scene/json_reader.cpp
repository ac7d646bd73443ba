#include "scene/json_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>
#include <vector>

#include "util/edit_distance.h"

namespace lenslab {

namespace {

const char* type_name(const nlohmann::json& v) {
    switch (v.type()) {
        case nlohmann::json::value_t::null:
            return "null";
        case nlohmann::json::value_t::object:
            return "an object";
        case nlohmann::json::value_t::array:
            return "an array";
        case nlohmann::json::value_t::string:
            return "a string";
        case nlohmann::json::value_t::boolean:
            return "a boolean";
        default:
            return "a number";
    }
}

bool equal_ignoring_case(const std::string& a, const std::string& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
}

}  // namespace

std::string closest_match(const std::string& word, const std::vector<std::string>& candidates) {
    // A key in the wrong case ("Type", "RADIUS") is the likeliest slip, however many letters.
    for (const std::string& c : candidates) {
        if (equal_ignoring_case(word, c)) return c;
    }
    std::string best;
    size_t best_distance = 3;
    for (const std::string& c : candidates) {
        const size_t d = edit_distance(word, c);
        if (d < best_distance) {
            best_distance = d;
            best = c;
        }
    }
    return best;
}

using nlohmann::json;

std::string excerpt(const nlohmann::json& value) {
    constexpr size_t kMax = 60;
    // A scalar as JSON (strings quoted, control characters escaped), a nested array or
    // object as [...] or {...}: never recursing.
    auto flat = [](const json& v) -> std::string {
        if (v.is_array()) return v.empty() ? "[]" : "[...]";
        if (v.is_object()) return v.empty() ? "{}" : "{...}";
        if (v.is_string()) {
            // Only the start of a long string is shown.
            json cut = v.get_ref<const json::string_t&>().substr(0, kMax + 1);
            return cut.dump(-1, ' ', false, json::error_handler_t::replace);
        }
        return v.dump();
    };
    std::string out;
    if (value.is_array() || value.is_object()) {
        out = value.is_array() ? "[" : "{";
        bool first = true;
        for (auto it = value.begin(); it != value.end() && out.size() <= kMax; ++it) {
            out += first ? "" : ", ";
            first = false;
            if (value.is_object()) out += flat(json(it.key())) + ": ";
            out += flat(*it);
        }
        out += value.is_array() ? "]" : "}";
    } else {
        out = flat(value);
    }
    if (out.size() > kMax) {
        size_t cut = kMax - 3;
        // Not inside a UTF-8 sequence.
        while (cut > 0 && (static_cast<unsigned char>(out[cut]) & 0xC0) == 0x80) --cut;
        out = out.substr(0, cut) + "...";
    }
    return out;
}

std::string element_path(const std::string& array_path, size_t i) {
    return array_path + "[" + std::to_string(i) + "]";
}

std::string read_type_key(const nlohmann::json& j, const std::string& path) {
    if (!j.is_object()) throw SceneError(path, "must be an object { \"type\": ... }");
    const auto it = j.find("type");
    if (it == j.end()) throw_missing_key(j, path, "type");
    if (!it->is_string()) throw SceneError(path + ".type", "must be a string");
    return it->get<std::string>();
}

JsonObjectReader::JsonObjectReader(const nlohmann::json& value, std::string path,
                                   const std::vector<std::string>& allowed,
                                   const std::string& owner)
    : m_value(value), m_path(std::move(path)), m_allowed(allowed.begin(), allowed.end()) {
    if (!value.is_object()) {
        throw SceneError(m_path, std::string("must be an object, got ") + type_name(value));
    }
    for (const auto& [key, unused] : m_value.items()) {
        if (m_allowed.count(key)) continue;
        // A near miss is a typo; anything else is most likely another kind's key.
        const std::string best = closest_match(key, allowed);
        const std::string reason =
            !best.empty() ? "unknown key (did you mean '" + best + "'?)"
                          : (owner.empty() ? "unknown key" : "not a property of " + owner);
        throw SceneError(child_path(key), reason);
    }
}

std::string JsonObjectReader::child_path(const std::string& key) const {
    return m_path.empty() ? key : m_path + "." + key;
}

bool JsonObjectReader::has(const std::string& key) const {
    if (!m_allowed.count(key)) throw std::logic_error("JsonObjectReader: key not declared: " + key);
    return m_value.contains(key);
}

const nlohmann::json* JsonObjectReader::find(const std::string& key) {
    if (!m_allowed.count(key)) throw std::logic_error("JsonObjectReader: key not declared: " + key);
    const auto it = m_value.find(key);
    return it == m_value.end() ? nullptr : &*it;
}

void throw_missing_key(const nlohmann::json& object, const std::string& path,
                       const std::string& key) {
    const auto child = [&](const std::string& k) { return path.empty() ? k : path + "." + k; };
    if (object.is_object()) {
        for (const auto& [given, unused] : object.items()) {
            if (equal_ignoring_case(given, key)) {
                throw SceneError(child(given), "unknown key (did you mean '" + key + "'?)");
            }
        }
    }
    throw SceneError(child(key), "missing (required)");
}

const nlohmann::json& JsonObjectReader::require(const std::string& key) {
    const nlohmann::json* v = find(key);
    if (!v) throw_missing_key(m_value, m_path, key);
    return *v;
}

double JsonObjectReader::as_number(const nlohmann::json& v, const std::string& path) {
    if (!v.is_number())
        throw SceneError(path, std::string("must be a number, got ") + type_name(v));
    const double d = v.get<double>();
    // Scene values stay far from double's range, so squares and products cannot overflow.
    if (!(std::abs(d) <= kMaxSceneNumber)) {
        throw SceneError(path, "must be between -1e15 and 1e15, got " + format_number(d));
    }
    return d;
}

Vec3 JsonObjectReader::as_vec3(const nlohmann::json& v, const std::string& path) {
    if (!v.is_array() || v.size() != 3) {
        throw SceneError(path, std::string("must be an array of 3 numbers [x, y, z], got ") +
                                   (v.is_array() ? "an array of " + std::to_string(v.size())
                                                 : std::string(type_name(v))));
    }
    Vec3 out;
    for (int i = 0; i < 3; ++i) out[i] = as_number(v[i], path + "[" + std::to_string(i) + "]");
    return out;
}

Rgb JsonObjectReader::as_color(const nlohmann::json& v, const std::string& path,
                               double max_component) {
    auto component = [&](const nlohmann::json& value, const std::string& where) {
        const double c = as_number(value, where);
        if (c < 0) throw SceneError(where, "must be >= 0, got " + format_number(c));
        if (c > max_component) {
            throw SceneError(where, "must be <= " + format_number(max_component) +
                                        " (a surface cannot reflect more than it receives), got " +
                                        format_number(c));
        }
        return c;
    };
    if (v.is_number()) return Rgb::grey(component(v, path));
    if (v.is_array() && v.size() == 3) {
        return {component(v[0], path + "[0]"), component(v[1], path + "[1]"),
                component(v[2], path + "[2]")};
    }
    throw SceneError(path, std::string("must be a number or [r, g, b], got ") + type_name(v));
}

double JsonObjectReader::number(const std::string& key) {
    return as_number(require(key), child_path(key));
}

double JsonObjectReader::number(const std::string& key, double fallback) {
    const nlohmann::json* v = find(key);
    return v ? as_number(*v, child_path(key)) : fallback;
}

double JsonObjectReader::positive(const std::string& key) {
    const double v = number(key);
    if (!(v > 0)) throw SceneError(child_path(key), "must be > 0, got " + format_number(v));
    return v;
}

double JsonObjectReader::positive(const std::string& key, double fallback) {
    return has(key) ? positive(key) : fallback;
}

int64_t JsonObjectReader::integer(const std::string& key, int64_t fallback, int64_t min_value,
                                  int64_t max_value) {
    const nlohmann::json* v = find(key);
    if (!v) return fallback;
    const double d = as_number(*v, child_path(key));
    if (d != std::floor(d)) {
        throw SceneError(child_path(key), "must be a whole number, got " + format_number(d));
    }
    if (d < static_cast<double>(min_value) || d > static_cast<double>(max_value)) {
        throw SceneError(child_path(key), "must be between " + std::to_string(min_value) + " and " +
                                              std::to_string(max_value) + ", got " +
                                              format_number(d));
    }
    return static_cast<int64_t>(d);
}

std::string JsonObjectReader::choice(const std::string& key, const std::string& fallback,
                                     const std::vector<std::string>& choices) {
    const std::string v = string(key, fallback);
    std::string known;
    for (const std::string& c : choices) {
        if (v == c) return v;
        known += (known.empty() ? "" : ", ") + c;
    }
    throw SceneError(child_path(key), "unknown " + key + " '" + v + "' (known: " + known + ")");
}

std::string JsonObjectReader::string(const std::string& key) {
    const nlohmann::json& v = require(key);
    if (!v.is_string()) {
        throw SceneError(child_path(key), std::string("must be a string, got ") + type_name(v));
    }
    return v.get<std::string>();
}

std::string JsonObjectReader::string(const std::string& key, const std::string& fallback) {
    return has(key) ? string(key) : fallback;
}

Vec3 JsonObjectReader::vec3(const std::string& key) {
    return as_vec3(require(key), child_path(key));
}

Vec3 JsonObjectReader::direction(const std::string& key) {
    const Vec3 v = vec3(key);
    const double len = length(v);
    if (!(len > 1e-12)) throw SceneError(child_path(key), "must be a non-zero vector");
    return v / len;
}

Vec3 JsonObjectReader::direction(const std::string& key, const Vec3& fallback) {
    return has(key) ? direction(key) : fallback;
}

Rgb JsonObjectReader::color(const std::string& key, const Rgb& fallback) {
    const nlohmann::json* v = find(key);
    return v ? as_color(*v, child_path(key)) : fallback;
}

Rgb JsonObjectReader::albedo(const std::string& key, const Rgb& fallback) {
    const nlohmann::json* v = find(key);
    return v ? as_color(*v, child_path(key), 1.0) : fallback;
}

std::optional<bool> JsonObjectReader::boolean(const std::string& key) {
    const nlohmann::json* v = find(key);
    if (!v) return std::nullopt;
    if (!v->is_boolean())
        throw SceneError(child_path(key),
                         std::string("must be true or false, got ") + type_name(*v));
    return v->get<bool>();
}

double JsonObjectReader::fraction(const std::string& key, double fallback) {
    const double v = number(key, fallback);
    if (v < 0 || v > 1) {
        throw SceneError(child_path(key), "must be between 0 and 1, got " + format_number(v));
    }
    return v;
}

}  // namespace lenslab
