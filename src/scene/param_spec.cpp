#include "scene/param_spec.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <stdexcept>

#include "geometry/plane_frame.h"
#include "scene/json_reader.h"
#include "scene/light.h"

namespace lenslab {

namespace {

using nlohmann::json;

ParamSpec make(std::string key, ParamKind kind, json fallback) {
    ParamSpec p;
    p.key = std::move(key);
    p.kind = kind;
    p.fallback = std::move(fallback);
    return p;
}

// A grey colour is written as one number, as the docs and most scenes do.
json colour_json(const Rgb& c) {
    if (c.r == c.g && c.g == c.b) return c.r;
    return json::array({c.r, c.g, c.b});
}

std::string suffix(const ParamSpec& p) {
    return (p.unit.empty() ? "" : " " + p.unit) + (p.why.empty() ? "" : " (" + p.why + ")");
}

// Large powers of two read better as such: 2^40 rather than 1099511627776.
std::string whole_text(double v) {
    const int exponent = std::ilogb(v);
    if (v >= std::ldexp(1.0, 30) && v == std::ldexp(1.0, exponent)) {
        return "2^" + std::to_string(exponent);
    }
    return format_number(v);
}

std::string value_text(const json& v) {
    if (v.is_number()) return format_number(v.get<double>());
    if (v.is_array()) {
        std::string out = "[";
        for (size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + value_text(v[i]);
        return out + "]";
    }
    return v.dump();
}

}  // namespace

std::string ParamSpec::option_name() const {
    std::string name = "--" + key;
    for (char& c : name) c = c == '_' ? '-' : c;
    return name;
}

ParamSpec number_param(std::string key, double fallback) {
    return make(std::move(key), ParamKind::Number, fallback);
}

ParamSpec whole_param(std::string key, int64_t fallback, int64_t min, int64_t max) {
    ParamSpec p = make(std::move(key), ParamKind::WholeNumber, fallback);
    p.min = Bound{double(min)};
    p.max = Bound{double(max)};
    p.decimals = 0;
    return p;
}

ParamSpec fraction_param(std::string key, double fallback) {
    return make(std::move(key), ParamKind::Fraction, fallback);
}

ParamSpec flag_param(std::string key, bool fallback) {
    return make(std::move(key), ParamKind::Boolean, fallback);
}

ParamSpec choice_param(std::string key, std::string fallback, std::vector<std::string> choices) {
    ParamSpec p = make(std::move(key), ParamKind::Choice, std::move(fallback));
    p.choices = std::move(choices);
    return p;
}

ParamSpec string_param(std::string key, std::string fallback) {
    return make(std::move(key), ParamKind::String, std::move(fallback));
}

ParamSpec colour_param(std::string key, const Rgb& fallback) {
    return make(std::move(key), ParamKind::Colour, colour_json(fallback));
}

ParamSpec albedo_param(std::string key, const Rgb& fallback) {
    return make(std::move(key), ParamKind::Albedo, colour_json(fallback));
}

ParamSpec point_param(std::string key) {
    ParamSpec p = make(std::move(key), ParamKind::Point, nullptr);
    p.required = true;
    return p;
}

ParamSpec direction_param(std::string key) {
    ParamSpec p = make(std::move(key), ParamKind::Direction, nullptr);
    p.required = true;
    return p;
}

ParamSpec vector_param(ParamKind kind, std::string key, const json& fallback) {
    return make(std::move(key), kind, fallback);
}

ParamSpec nested_param(ParamKind kind, std::string key) {
    return make(std::move(key), kind, nullptr);
}

const ParamSpec* ElementSpec::find(const std::string& key) const {
    for (const ParamSpec& p : params) {
        if (p.key == key) return &p;
    }
    return nullptr;
}

const ParamSpec& ElementSpec::param(const std::string& key) const {
    if (const ParamSpec* p = find(key)) return *p;
    throw std::logic_error("ElementSpec " + name + ": no parameter " + key);
}

std::vector<std::string> ElementSpec::keys() const {
    std::vector<std::string> out;
    for (const ParamSpec& p : params) out.push_back(p.key);
    return out;
}

std::optional<std::string> range_problem(const ParamSpec& p, double v) {
    // Formatted only for a message: a scene reads many numbers and almost all are in range.
    const auto got = [v] { return ", got " + format_number(v); };
    if (p.kind == ParamKind::WholeNumber) {
        if (!(v >= p.min->value && v <= p.max->value)) {
            return "must be between " + std::to_string(int64_t(p.min->value)) + " and " +
                   std::to_string(int64_t(p.max->value)) + got();
        }
        return std::nullopt;
    }
    if (p.kind == ParamKind::Fraction) {
        if (!(v >= 0 && v <= 1)) return "must be between 0 and 1" + got();
        // A fraction's floor is a second, separate rule with its own reason.
        if (p.min && !(v >= p.min->value)) {
            return "must be at least " + format_number(p.min->value) + suffix(p) + got();
        }
        return std::nullopt;
    }
    const bool low = p.min && !(p.min->exclusive ? v > p.min->value : v >= p.min->value);
    const bool high = p.max && !(p.max->exclusive ? v < p.max->value : v <= p.max->value);
    if (!low && !high && !std::isnan(v)) return std::nullopt;
    if (p.min && p.max) {
        const std::string unit = p.unit.empty() ? "" : " " + p.unit;
        const std::string why = p.why.empty() ? "" : " (" + p.why + ")";
        if (p.min->exclusive != p.max->exclusive) {  // one end allowed, the other not
            return std::string("must be ") + (p.min->exclusive ? "above " : "at least ") +
                   format_number(p.min->value) +
                   (p.max->exclusive ? " and below " : " and at most ") +
                   format_number(p.max->value) + unit + why + got();
        }
        return "must be between " + format_number(p.min->value) + " and " +
               format_number(p.max->value) + unit + (p.min->exclusive ? " (exclusive)" : "") + why +
               got();
    }
    if (p.min) {
        return std::string("must be ") + (p.min->exclusive ? "> " : ">= ") +
               format_number(p.min->value) + suffix(p) + got();
    }
    if (p.max) {
        return std::string("must be ") + (p.max->exclusive ? "< " : "<= ") +
               format_number(p.max->value) + suffix(p) + got();
    }
    return "must be a number" + got();  // NaN, from a command line
}

std::optional<std::string> choice_problem(const ParamSpec& p, const std::string& v) {
    std::string known;
    for (const std::string& c : p.choices) {
        if (v == c) return std::nullopt;
        known += (known.empty() ? "" : ", ") + c;
    }
    return "unknown " + p.key + " '" + v + "' (known: " + known + ")";
}

bool fallback_in_range(const ParamSpec& p) {
    if (!p.fallback.is_number()) return true;
    return !range_problem(p, p.fallback.get<double>());
}

std::string kind_text(const ParamSpec& p) {
    if (!p.written_as.empty()) return p.written_as;
    std::string text;
    switch (p.kind) {
        case ParamKind::Number:
            text = "number";
            break;
        case ParamKind::WholeNumber:
            text = "whole number";
            break;
        case ParamKind::Boolean:
            text = "`true` or `false`";
            break;
        case ParamKind::Choice:
            text = "string";
            break;
        case ParamKind::String:
            text = "string";
            break;
        case ParamKind::Point:
            text = "point";
            break;
        case ParamKind::Direction:
            text = "direction";
            break;
        case ParamKind::Colour:
            text = "colour";
            break;
        case ParamKind::Albedo:
            text = "colour, each component in [0, 1]";
            break;
        case ParamKind::Fraction:
            text = "fraction";
            break;
        case ParamKind::Object:
            text = "object";
            break;
        case ParamKind::Array:
            text = "array";
            break;
    }
    return p.unit.empty() ? text : text + ", " + p.unit;
}

std::string default_text(const ParamSpec& p) {
    if (p.required) return "**required**";
    if (p.fallback.is_null()) return p.auto_meaning.empty() ? "—" : p.auto_meaning;
    if (!fallback_in_range(p) && !p.auto_meaning.empty()) return p.auto_meaning;
    const std::string value = "`" + value_text(p.fallback) + "`";
    return p.auto_meaning.empty() ? value : value + " (" + p.auto_meaning + ")";
}

std::string range_text(const ParamSpec& p) {
    switch (p.kind) {
        case ParamKind::WholeNumber:
            return whole_text(p.min->value) + " – " + whole_text(p.max->value);
        case ParamKind::Fraction:
            return p.min ? "[" + format_number(p.min->value) + ", 1]" : "[0, 1]";
        case ParamKind::Colour:
            return "`>= 0`";
        case ParamKind::Choice: {
            std::string out;
            for (const std::string& c : p.choices)
                out += (out.empty() ? "`\"" : ", `\"") + c + "\"`";
            return out;
        }
        case ParamKind::Number:
            if (p.min && p.max) {
                return (p.min->exclusive ? "(" : "[") + format_number(p.min->value) + ", " +
                       format_number(p.max->value) + (p.max->exclusive ? ")" : "]");
            }
            if (p.min)
                return std::string("`") + (p.min->exclusive ? "> " : ">= ") +
                       format_number(p.min->value) + "`";
            if (p.max)
                return std::string("`") + (p.max->exclusive ? "< " : "<= ") +
                       format_number(p.max->value) + "`";
            return "";
        case ParamKind::Object:
        case ParamKind::Array:
            // A count that may also be written as an array (a detector's cells).
            if (p.min && p.max)
                return format_number(p.min->value) + " – " + format_number(p.max->value);
            return "";
        default:
            return "";
    }
}

namespace {

// `p` moved by `offset`, when it is a point [x, y, z] of numbers.
void move_point(nlohmann::json& p, const Vec3& offset) {
    if (!p.is_array() || p.size() != 3) return;
    for (int a = 0; a < 3; ++a) {
        if (!p[a].is_number()) return;
    }
    for (int a = 0; a < 3; ++a) p[a] = p[a].get<double>() + offset[a];
}

// `v` turned by `angle` about the unit `k` (Rodrigues' formula).
Vec3 spec_turned_vector(const Vec3& v, const Vec3& k, double angle) {
    return v * std::cos(angle) + cross(k, v) * std::sin(angle) +
           k * (dot(k, v) * (1 - std::cos(angle)));
}

// `p` as a vector, when it is [x, y, z] of numbers; other shapes are left for the reader.
std::optional<Vec3> spec_vector_of(const nlohmann::json& p) {
    if (!p.is_array() || p.size() != 3) return std::nullopt;
    for (int a = 0; a < 3; ++a) {
        if (!p[a].is_number()) return std::nullopt;
    }
    return Vec3{p[0].get<double>(), p[1].get<double>(), p[2].get<double>()};
}

void spec_rewrite_vector(nlohmann::json& p, const std::function<Vec3(const Vec3&)>& f) {
    if (const std::optional<Vec3> v = spec_vector_of(p)) {
        const Vec3 out = f(*v);
        p = nlohmann::json::array({out.x, out.y, out.z});
    }
}

}  // namespace

nlohmann::json moved_element(const ElementSpec& spec, nlohmann::json element, const Vec3& offset) {
    if (!element.is_object()) return element;
    for (const ParamSpec& p : spec.params) {
        auto it = element.find(p.key);
        if (p.kind == ParamKind::Point) {
            if (it == element.end() && p.fallback.is_null()) continue;
            nlohmann::json& point = it != element.end() ? *it : (element[p.key] = p.fallback);
            move_point(point, offset);
        } else if (p.positions && it != element.end() && it->is_array()) {
            for (nlohmann::json& point : *it) move_point(point, offset);
        }
    }
    return element;
}

nlohmann::json rotated_element(const ElementSpec& spec, nlohmann::json element, const Vec3& pivot,
                               const Vec3& axis, double angle) {
    if (!element.is_object()) return element;
    const auto turn_point = [&](const Vec3& p) {
        return pivot + spec_turned_vector(p - pivot, axis, angle);
    };
    const auto turn_direction = [&](const Vec3& d) { return spec_turned_vector(d, axis, angle); };
    // A flat shape's automatic up, as the reader would choose it from the normal now.
    const ParamSpec* up = spec.find("up");
    if (up && up->fallback.is_null() && spec.find("normal") && !element.contains("up") &&
        element.contains("normal")) {
        if (const std::optional<Vec3> normal = spec_vector_of(element["normal"])) {
            const Vec3 u = default_plane_up(normalize(*normal));
            element["up"] = nlohmann::json::array({u.x, u.y, u.z});
        }
    }
    // A beam's automatic slit and fan axes, likewise, where it has a slit or a fan.
    const auto write_beam_axis = [&](const char* shape, const char* key,
                                     Vec3 (*automatic)(const Vec3&)) {
        const ParamSpec* declared = spec.find(key);
        const auto size = element.find(shape);
        if (!declared || element.contains(key) || size == element.end() || !size->is_number() ||
            !(size->get<double>() > 0.0) || !element.contains("direction"))
            return;
        if (const std::optional<Vec3> d = spec_vector_of(element["direction"])) {
            if (!(length(*d) > 0.0)) return;
            const Vec3 a = automatic(normalize(*d));
            element[key] = nlohmann::json::array({a.x, a.y, a.z});
        }
    };
    write_beam_axis("slit_width", "slit_axis", default_slit_axis);
    write_beam_axis("fan_angle", "fan_axis", default_fan_axis);
    for (const ParamSpec& p : spec.params) {
        auto it = element.find(p.key);
        const bool point = p.kind == ParamKind::Point, direction = p.kind == ParamKind::Direction;
        if (point || direction) {
            if (it == element.end() && !p.fallback.is_array()) continue;
            nlohmann::json& v = it != element.end() ? *it : (element[p.key] = p.fallback);
            if (point)
                spec_rewrite_vector(v, turn_point);
            else
                spec_rewrite_vector(v, turn_direction);
        } else if (p.positions && it != element.end() && it->is_array()) {
            for (nlohmann::json& v : *it) spec_rewrite_vector(v, turn_point);
        }
    }
    return element;
}

bool element_turns(const ElementSpec& spec) {
    return std::any_of(spec.params.begin(), spec.params.end(), [](const ParamSpec& p) {
        return p.kind == ParamKind::Direction || p.positions;
    });
}

}  // namespace lenslab
