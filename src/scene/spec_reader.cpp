#include "scene/spec_reader.h"

#include <cmath>
#include <stdexcept>

namespace lenslab {

namespace {

Vec3 vec3_of(const nlohmann::json& v) {
    return {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
}

Rgb rgb_of(const nlohmann::json& v) {
    if (v.is_number()) return Rgb::grey(v.get<double>());
    return {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
}

}  // namespace

SpecReader::SpecReader(const nlohmann::json& value, std::string path, const ElementSpec& spec)
    : JsonObjectReader(value, std::move(path), spec.keys(), spec.phrase), m_spec(spec) {}

const ParamSpec& SpecReader::declared(const std::string& key, ParamKind a, ParamKind b) const {
    const ParamSpec& p = m_spec.param(key);
    if (p.kind != a && p.kind != b) {
        throw std::logic_error("SpecReader: " + m_spec.name + "." + key + " read as another kind");
    }
    if (p.required || !p.fallback.is_null()) return p;
    if (!has(key))
        throw std::logic_error("SpecReader: " + key + " has no fallback; check has() first");
    return p;
}

double SpecReader::real(const std::string& key) {
    const ParamSpec& p = declared(key, ParamKind::Number, ParamKind::Fraction);
    if (!p.required && !has(key)) return p.fallback.get<double>();
    const double v = number(key);
    if (auto problem = range_problem(p, v)) throw SceneError(child_path(key), *problem);
    return v;
}

int64_t SpecReader::whole(const std::string& key) {
    const ParamSpec& p = declared(key, ParamKind::WholeNumber, ParamKind::WholeNumber);
    if (!p.required && !has(key)) return p.fallback.get<int64_t>();
    const double d = number(key);
    if (d != std::floor(d)) {
        throw SceneError(child_path(key), "must be a whole number, got " + format_number(d));
    }
    if (auto problem = range_problem(p, d)) throw SceneError(child_path(key), *problem);
    return static_cast<int64_t>(d);
}

bool SpecReader::flag(const std::string& key) {
    const ParamSpec& p = declared(key, ParamKind::Boolean, ParamKind::Boolean);
    return boolean(key).value_or(p.fallback.is_boolean() && p.fallback.get<bool>());
}

std::string SpecReader::text(const std::string& key) {
    const ParamSpec& p = declared(key, ParamKind::String, ParamKind::Choice);
    const std::string v = p.required ? string(key) : string(key, p.fallback.get<std::string>());
    if (p.kind == ParamKind::Choice) {
        if (auto problem = choice_problem(p, v)) throw SceneError(child_path(key), *problem);
    }
    return v;
}

Rgb SpecReader::colour(const std::string& key) {
    const ParamSpec& p = declared(key, ParamKind::Colour, ParamKind::Albedo);
    if (!p.required && !has(key)) return rgb_of(p.fallback);
    return as_color(require(key), child_path(key), p.kind == ParamKind::Albedo ? 1.0 : INFINITY);
}

Vec3 SpecReader::point(const std::string& key) {
    const ParamSpec& p = declared(key, ParamKind::Point, ParamKind::Point);
    if (!p.required && !has(key)) return vec3_of(p.fallback);
    return vec3(key);
}

Vec3 SpecReader::unit_vector(const std::string& key) {
    const ParamSpec& p = declared(key, ParamKind::Direction, ParamKind::Direction);
    if (!p.required && !has(key)) return normalize(vec3_of(p.fallback));
    return direction(key);
}

}  // namespace lenslab
