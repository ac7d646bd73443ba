#include "scene/json_reader.h"

#include <cmath>
#include <sstream>
#include <vector>

namespace lenslab {

namespace {

const char* type_name(const nlohmann::json& v) {
    switch (v.type()) {
        case nlohmann::json::value_t::null: return "null";
        case nlohmann::json::value_t::object: return "an object";
        case nlohmann::json::value_t::array: return "an array";
        case nlohmann::json::value_t::string: return "a string";
        case nlohmann::json::value_t::boolean: return "a boolean";
        default: return "a number";
    }
}

// Levenshtein distance, for "did you mean" suggestions on unknown keys.
size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = above;
        }
    }
    return row[b.size()];
}

}  // namespace

std::string format_number(double v) {
    std::ostringstream s;
    s.precision(10);
    s << v;
    return s.str();
}

JsonObjectReader::JsonObjectReader(const nlohmann::json& value, std::string path,
                                   std::initializer_list<const char*> allowed)
    : m_value(value), m_path(std::move(path)), m_allowed(allowed.begin(), allowed.end()) {
    if (!value.is_object()) {
        throw SceneError(m_path, std::string("must be an object, got ") + type_name(value));
    }
    for (const auto& [key, unused] : m_value.items()) {
        if (m_allowed.count(key)) continue;
        std::string reason = "unknown key";
        std::string best;
        size_t best_distance = 3;  // suggest only close spellings
        for (const std::string& known : m_allowed) {
            const size_t d = edit_distance(key, known);
            if (d < best_distance) {
                best_distance = d;
                best = known;
            }
        }
        if (!best.empty()) reason += " (did you mean '" + best + "'?)";
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

const nlohmann::json& JsonObjectReader::require(const std::string& key) {
    const nlohmann::json* v = find(key);
    if (!v) throw SceneError(child_path(key), "missing (required)");
    return *v;
}

double JsonObjectReader::as_number(const nlohmann::json& v, const std::string& path) {
    if (!v.is_number()) throw SceneError(path, std::string("must be a number, got ") + type_name(v));
    const double d = v.get<double>();
    if (!std::isfinite(d)) throw SceneError(path, "must be finite");
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

Rgb JsonObjectReader::as_color(const nlohmann::json& v, const std::string& path) {
    Rgb c;
    if (v.is_number()) {
        c = Rgb::grey(as_number(v, path));
    } else if (v.is_array() && v.size() == 3) {
        c = {as_number(v[0], path + "[0]"), as_number(v[1], path + "[1]"),
             as_number(v[2], path + "[2]")};
    } else {
        throw SceneError(path, std::string("must be a number or [r, g, b], got ") + type_name(v));
    }
    if (c.r < 0 || c.g < 0 || c.b < 0) throw SceneError(path, "components must be >= 0");
    return c;
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

int JsonObjectReader::integer(const std::string& key, int fallback, int min_value, int max_value) {
    const nlohmann::json* v = find(key);
    if (!v) return fallback;
    const double d = as_number(*v, child_path(key));
    if (d != std::floor(d)) {
        throw SceneError(child_path(key), "must be a whole number, got " + format_number(d));
    }
    if (d < min_value || d > max_value) {
        throw SceneError(child_path(key), "must be between " + std::to_string(min_value) +
                                              " and " + std::to_string(max_value) + ", got " +
                                              format_number(d));
    }
    return static_cast<int>(d);
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

Vec3 JsonObjectReader::vec3(const std::string& key) { return as_vec3(require(key), child_path(key)); }

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

double JsonObjectReader::fraction(const std::string& key, double fallback) {
    const double v = number(key, fallback);
    if (v < 0 || v > 1) {
        throw SceneError(child_path(key), "must be between 0 and 1, got " + format_number(v));
    }
    return v;
}

}  // namespace lenslab
