#pragma once
// A JsonObjectReader that takes its keys, defaults and ranges from an element's declaration
// (param_spec.h): unknown keys are refused as before, and each value is read, defaulted and
// range-checked as declared. Rules between fields stay with the element's reading code.

#include <string>

#include "scene/json_reader.h"
#include "scene/param_spec.h"

namespace lenslab {

class SpecReader : public JsonObjectReader {
public:
    SpecReader(const nlohmann::json& value, std::string path, const ElementSpec& spec);

    const ElementSpec& spec() const { return m_spec; }

    // Each reads the declared key (of the matching kind): the declared fallback when absent
    // (a required one throws "missing (required)"), and refuses a value out of range.
    double real(const std::string& key);       // Number, Fraction
    int64_t whole(const std::string& key);     // WholeNumber
    bool flag(const std::string& key);         // Boolean
    std::string text(const std::string& key);  // String, Choice
    Rgb colour(const std::string& key);        // Colour, Albedo
    Vec3 point(const std::string& key);        // Point
    Vec3 unit_vector(const std::string& key);  // Direction, normalised

private:
    const ParamSpec& declared(const std::string& key, ParamKind a, ParamKind b) const;

    const ElementSpec& m_spec;
};

}  // namespace lenslab
