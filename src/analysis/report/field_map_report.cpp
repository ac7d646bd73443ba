#include "analysis/report/field_map_report.h"

#include <cmath>
#include <cstdio>

namespace lenslab {

nlohmann::ordered_json field_map_json(const OpticalSystem& system, const FieldMap& map) {
    nlohmann::ordered_json j;
    j["wavelength_nm"] = map.options.wavelength_nm;
    j["image_z"] = map.options.image_z;
    j["image_position"] = map.options.image_z - system.last_vertex();
    j["rings"] = map.options.rings;
    j["fields_x"] = map.fields_x;
    j["fields_y"] = map.fields_y;
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (const std::vector<double>& row : map.rms) {
        nlohmann::ordered_json r = nlohmann::ordered_json::array();
        for (double v : row) r.push_back(std::isfinite(v) ? nlohmann::ordered_json(v) : nullptr);
        rows.push_back(r);
    }
    j["rms"] = rows;
    return j;
}

std::string field_map_table(const OpticalSystem& system, const FieldMap& map) {
    std::string out;
    char line[96];
    std::snprintf(line, sizeof line,
                  "\nField map: RMS spot radius at %.2f nm in the plane %.4f from the last "
                  "vertex;\n",
                  map.options.wavelength_nm, map.options.image_z - system.last_vertex());
    out += line;
    out += "rows: field y (top: largest), columns: field x\n";
    std::snprintf(line, sizeof line, "%10s", "y \\ x");
    out += line;
    for (double x : map.fields_x) {
        std::snprintf(line, sizeof line, " %11.4g", x);
        out += line;
    }
    out += "\n";
    for (size_t j = map.fields_y.size(); j-- > 0;) {
        std::snprintf(line, sizeof line, "%10.4g", map.fields_y[j]);
        out += line;
        for (double v : map.rms[j]) {
            if (std::isfinite(v)) {
                std::snprintf(line, sizeof line, " %11.6f", v);
            } else {
                std::snprintf(line, sizeof line, " %11s", "-");
            }
            out += line;
        }
        out += "\n";
    }
    return out;
}

}  // namespace lenslab
