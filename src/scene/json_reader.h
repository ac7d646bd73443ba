#pragma once
// Reads one JSON object while remembering where it is ("objects[2].front"), so every error
// names the exact path, and refuses keys nobody asked for, so typos never pass silently.

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "math/vec3.h"
#include "optics/rgb.h"
#include "scene/json_strict_parse.h"
#include "util/format_number.h"
#include "util/scene_error.h"

namespace lenslab {

// Largest magnitude any number in a scene file may have.
inline constexpr double kMaxSceneNumber = 1e15;

// A bounded, flat excerpt of an input value for messages that quote it: at most about 60
// characters, arrays and objects inside the value shown as [...] and {...} (so it never
// recurses, however deep the value), control characters escaped.
std::string excerpt(const nlohmann::json& value);

// The path of an array's element: "objects" and 2 give "objects[2]".
std::string element_path(const std::string& array_path, size_t i);

// The `type` of an object or light, read first: it decides which other keys belong. Throws
// SceneError at `path` when the value is no object, or its type is missing or no string.
std::string read_type_key(const nlohmann::json& j, const std::string& path);

// The candidate spelled most like `word` (at most 2 edits away), or "" if none is close:
// for "did you mean" hints.
std::string closest_match(const std::string& word, const std::vector<std::string>& candidates);

// Throws SceneError(path.KEY, "missing (required)") for a required `key` that `object` lacks,
// or, when it holds the key in another case ("Type" for "type"), points at that key instead:
// "unknown key (did you mean 'type'?)". Keys are case-sensitive.
[[noreturn]] void throw_missing_key(const nlohmann::json& object, const std::string& path,
                                    const std::string& key);

class JsonObjectReader {
public:
    // Throws if `value` is not a JSON object, or if it holds a key not in `allowed` (with a
    // "did you mean" suggestion). Every key the reader is later asked for must be allowed.
    // `owner` ("a sphere") words the refusal of a key another kind of object would take:
    // "not a property of a sphere".
    JsonObjectReader(const nlohmann::json& value, std::string path,
                     const std::vector<std::string>& allowed, const std::string& owner = "");

    const std::string& path() const { return m_path; }
    std::string child_path(const std::string& key) const;
    bool has(const std::string& key) const;

    // Raw access. `require` throws if the key is missing.
    const nlohmann::json& require(const std::string& key);
    const nlohmann::json* find(const std::string& key);

    double number(const std::string& key);
    double number(const std::string& key, double fallback);
    double positive(const std::string& key);  // > 0
    double positive(const std::string& key, double fallback);
    int64_t integer(const std::string& key, int64_t fallback, int64_t min_value, int64_t max_value);
    // A string that must be one of `choices` (the message lists them).
    std::string choice(const std::string& key, const std::string& fallback,
                       const std::vector<std::string>& choices);
    std::string string(const std::string& key);
    std::string string(const std::string& key, const std::string& fallback);
    Vec3 vec3(const std::string& key);
    Vec3 direction(const std::string& key);  // non-zero, returned normalised
    Vec3 direction(const std::string& key, const Vec3& fallback);
    // A colour: a number (grey) or [r, g, b], each >= 0 and finite.
    Rgb color(const std::string& key, const Rgb& fallback);
    // A reflectance colour: as `color`, each component also <= 1 (energy conservation).
    Rgb albedo(const std::string& key, const Rgb& fallback);
    double fraction(const std::string& key, double fallback);  // in [0, 1]
    std::optional<bool> boolean(const std::string& key);       // unset when absent

    // Helpers for values that are not members of an object reader.
    static double as_number(const nlohmann::json& v, const std::string& path);
    static Vec3 as_vec3(const nlohmann::json& v, const std::string& path);
    static Rgb as_color(const nlohmann::json& v, const std::string& path,
                        double max_component = INFINITY);

private:
    const nlohmann::json& m_value;
    std::string m_path;
    std::set<std::string> m_allowed;
};

}  // namespace lenslab
