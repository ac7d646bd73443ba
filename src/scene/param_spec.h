#pragma once
// A scene element's parameters declared once: key, kind, default, valid range, unit, one
// line of documentation and the editor's label. The scene reader, the command line's
// overrides, the editor's forms and the docs test all read these declarations, so a range or
// a default cannot disagree between them.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "math/vec3.h"
#include "optics/rgb.h"

namespace lenslab {

enum class ParamKind {
    Number,       // any finite number (within the scene's magnitude limit)
    WholeNumber,  // a number with no fractional part
    Boolean,
    Choice,  // a string, one of `choices`
    String,
    Point,
    Direction,  // a non-zero vector, normalised when read
    Colour,     // a number (grey) or [r, g, b], each >= 0
    Albedo,     // a colour with each component in [0, 1]
    Fraction,   // a number in [0, 1]
    Object,     // nested things read by their own code
    Array,
};

// One end of a valid range.
struct Bound {
    double value;
    bool exclusive = false;
};

struct ParamSpec {
    std::string key;
    ParamKind kind = ParamKind::Number;
    // What the reader uses when the key is absent; null with `required` or no default.
    nlohmann::json fallback;
    bool required = false;
    // What the fallback means when it is a stand-in ("auto: 0.5% of the scene's diagonal").
    // A fallback outside the range is only ever implied by leaving the key out.
    std::string auto_meaning;
    std::optional<Bound> min, max;
    std::vector<std::string> choices;
    std::string unit;        // "degrees", "seconds": in messages and the docs' type column
    std::string written_as;  // the docs' type words where the kind's own do not say it
    std::string why;         // why the range is what it is, added to the refusal
    std::string doc;         // one line: the CLI's option help
    std::string label;       // the editor's field label; empty: not in the editor's form
    std::string group;       // the editor's heading above the field ("Photon map")
    bool cli = false;  // `lenslab render --KEY` overrides it (the option names are a contract)
    bool positions = false;  // an array of points that move with the element (its vertices)
    int decimals = 6;        // digits the editor shows
    // An array of numbers: how many it holds (most 0: not such an array).
    size_t least_count = 0, most_count = 0;

    // Chained setters keep each declaration one readable expression.
    ParamSpec& above(double v) { return (min = Bound{v, true}, *this); }
    ParamSpec& at_least(double v) { return (min = Bound{v, false}, *this); }
    ParamSpec& below(double v) { return (max = Bound{v, true}, *this); }
    ParamSpec& at_most(double v) { return (max = Bound{v, false}, *this); }
    ParamSpec& in_unit(std::string u) { return (unit = std::move(u), *this); }
    ParamSpec& because(std::string text) { return (why = std::move(text), *this); }
    ParamSpec& meaning_auto(std::string text) { return (auto_meaning = std::move(text), *this); }
    ParamSpec& describe(std::string text) { return (doc = std::move(text), *this); }
    // `digits` < 0 keeps the kind's own (none for whole numbers, else 6).
    ParamSpec& in_editor(std::string text, int digits = -1) {
        return (label = std::move(text), decimals = digits < 0 ? decimals : digits, *this);
    }
    ParamSpec& under(std::string heading) { return (group = std::move(heading), *this); }
    ParamSpec& on_command_line() { return (cli = true, *this); }
    ParamSpec& needed() { return (required = true, fallback = nullptr, *this); }
    ParamSpec& as_written(std::string words) { return (written_as = std::move(words), *this); }
    ParamSpec& of_positions() { return (positions = true, *this); }
    // An array of `least` to `most` numbers (the editor's comma-separated list).
    ParamSpec& holding_numbers(size_t least, size_t most) {
        kind = ParamKind::Array;
        least_count = least;
        most_count = most;
        written_as =
            "array of " + std::to_string(least) + " to " + std::to_string(most) + " numbers";
        return *this;
    }

    bool is_integer() const { return kind == ParamKind::WholeNumber; }
    // The command-line option for this key: "max_depth" -> "--max-depth".
    std::string option_name() const;
};

// Starting points for declarations, one per kind.
ParamSpec number_param(std::string key, double fallback);
ParamSpec whole_param(std::string key, int64_t fallback, int64_t min, int64_t max);
ParamSpec fraction_param(std::string key, double fallback);
ParamSpec flag_param(std::string key, bool fallback);
ParamSpec choice_param(std::string key, std::string fallback, std::vector<std::string> choices);
ParamSpec string_param(std::string key, std::string fallback);
ParamSpec colour_param(std::string key, const Rgb& fallback);
ParamSpec albedo_param(std::string key, const Rgb& fallback);
ParamSpec point_param(std::string key);      // required
ParamSpec direction_param(std::string key);  // required
ParamSpec vector_param(ParamKind kind, std::string key, const nlohmann::json& fallback);
ParamSpec nested_param(ParamKind kind, std::string key);  // optional object or array

// An element type's parameters: the render block, the camera, a sphere.
struct ElementSpec {
    std::string name;    // "render", "camera", "sphere"
    std::string phrase;  // "a sphere", for "not a property of a sphere"
    std::vector<ParamSpec> params;
    // What a new element of this type starts as, around the origin: the editor's "Add" moves
    // it (moved_element) to where it is put. For a lens surface shape, a valid surface of it
    // (the docs test reads it); null for other parts of an element.
    nlohmann::json example;

    const ParamSpec& param(const std::string& key) const;  // throws std::logic_error
    const ParamSpec* find(const std::string& key) const;
    std::vector<std::string> keys() const;
};

// Why `v` is outside p's range ("must be between 0 and 180 degrees (exclusive), got 180"), or
// nothing. Numbers only; the caller has checked it is a number (and whole, for whole numbers).
std::optional<std::string> range_problem(const ParamSpec& p, double v);
// Why `v` is not one of p's choices ("unknown integrator 'bdpt' (known: ...)"), or nothing.
std::optional<std::string> choice_problem(const ParamSpec& p, const std::string& v);

// The docs' reference-table cells for a parameter (docs/scene-format.md).
std::string kind_text(const ParamSpec& p);     // "whole number", "number, degrees"
std::string default_text(const ParamSpec& p);  // "`640`", "**required**", "auto"
std::string range_text(const ParamSpec& p);    // "1 – 16384", "`>= 0`", "(0, 180)"

// `element` (of type `spec`) moved by `offset`: its Point parameters (a declared default
// standing in for an absent one) and its arrays of positions. Values of the wrong shape are
// left for the reader to refuse.
nlohmann::json moved_element(const ElementSpec& spec, nlohmann::json element, const Vec3& offset);

// `element` (of type `spec`) turned by `angle` radians about the line through `pivot` along
// the unit `axis`: its points and positions turn about the line, its directions (axis,
// normal, up, facing) with it. An absent direction with a declared default is written out
// turned; a flat shape's automatic up too, else a turn about its normal would not show.
nlohmann::json rotated_element(const ElementSpec& spec, nlohmann::json element, const Vec3& pivot,
                               const Vec3& axis, double angle);
// Whether rotated_element can turn an element of this type: it has a direction or positions
// (a sphere has neither; an implicit solid's formula does not turn).
bool element_turns(const ElementSpec& spec);

// Whether the fallback may also be written in a file (not merely implied by absence).
bool fallback_in_range(const ParamSpec& p);

}  // namespace lenslab
