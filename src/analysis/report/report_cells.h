#pragma once
// Numbers in the bench's JSON and tables where a figure may be missing (a vignetted ray, the
// axis's distortion): NaN prints as JSON null and as "-" in a table column, and a rounding
// error about zero prints as 0 rather than -0.

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace lenslab {

inline nlohmann::ordered_json json_number(double v) {
    return std::isnan(v) ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(v);
}

inline nlohmann::ordered_json json_numbers(const std::vector<double>& values) {
    nlohmann::ordered_json j = nlohmann::ordered_json::array();
    for (double v : values) j.push_back(json_number(v));
    return j;
}

// " %*.{decimals}f" in a column of `width` (a leading space included), or "-".
inline std::string table_cell(double v, int width, int decimals = 6) {
    char text[64];
    if (std::isnan(v)) {
        std::snprintf(text, sizeof text, "%*s", width, "-");
    } else {
        const double smallest = 0.5 * std::pow(10.0, -decimals);
        std::snprintf(text, sizeof text, "%*.*f", width, decimals,
                      std::abs(v) < smallest ? 0.0 : v);
    }
    return text;
}

}  // namespace lenslab
