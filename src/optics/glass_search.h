#pragma once
// Searching the glasses by maker, n_d and V_d: what `lenslab glass --maker --nd --vd` does.

#include <optional>
#include <string>
#include <vector>

#include "optics/glass.h"

namespace lenslab {

// A closed interval; either end may be open ("1.5:" is n_d >= 1.5).
struct ValueRange {
    double min = -1e300, max = 1e300;
    bool contains(double v) const { return v >= min && v <= max; }
};

// "1.5:1.6", "1.5:", ":1.6"; nullopt for anything else (not two numbers, min > max, NaN).
std::optional<ValueRange> parse_value_range(const std::string& text);

struct GlassQuery {
    std::string maker;  // "SCHOTT" (any case), "builtin" for the built-in materials, "" for all
    std::optional<ValueRange> n_d, v_d;
};

// n_d and V_d from the glass's model where it covers the C, d and F lines (what `lenslab glass`
// always printed), else the catalogue's printed values; NaN where there are neither.
double glass_n_d(const Glass& g);
double glass_v_d(const Glass& g);

// The built-in materials, then the users' catalogues loaded so far, then every maker's
// glasses, that match the query, in that order. A user catalogue's maker is its file's name.
std::vector<const Glass*> search_glasses(const GlassQuery& query);

}  // namespace lenslab
