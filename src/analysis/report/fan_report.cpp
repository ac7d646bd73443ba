#include "analysis/report/fan_report.h"

#include <cmath>
#include <cstdio>

#include "analysis/report/report_cells.h"

namespace lenslab {

namespace {

using Json = nlohmann::ordered_json;

}  // namespace

Json fans_json(const OpticalSystem& system, const RayFans& r, FanQuantity quantity) {
    Json j;
    j["image_z"] = r.image_z;
    j["image_position"] = r.image_z - system.last_vertex();
    if (quantity == FanQuantity::Opd) {
        j["reference"] = "each wavelength's chief ray and reference sphere";
        j["unit"] = "waves";
    } else {
        j["reference"] = "chief ray of the primary wavelength";
    }
    j["reference_wavelength_nm"] = r.primary_nm;
    j["pupil"] = r.pupil;
    Json fields = Json::array();
    for (const FieldFans& f : r.fields) {
        Json e;
        e["field"] = f.field;
        e["chief"] =
            f.reference ? Json{{"x", f.reference->x}, {"y", f.reference->y}} : Json(nullptr);
        Json fans = Json::array();
        for (const RayFan& fan : f.fans) {
            fans.push_back({{"wavelength", fan.wavelength_nm},
                            {"tangential", json_numbers(fan.tangential)},
                            {"sagittal", json_numbers(fan.sagittal)}});
        }
        e["fans"] = std::move(fans);
        fields.push_back(std::move(e));
    }
    j["fields"] = std::move(fields);
    return j;
}

std::string fans_table(const OpticalSystem& system, const RayFans& r, FanQuantity quantity) {
    const bool opd = quantity == FanQuantity::Opd;
    char line[200];
    if (opd) {
        std::snprintf(line, sizeof line,
                      "\nOPD fans in the plane %.4f from the last vertex, waves against each "
                      "wavelength's chief ray; tangential W(py), sagittal W(px)\n",
                      r.image_z - system.last_vertex());
    } else {
        std::snprintf(line, sizeof line,
                      "\nRay fans in the plane %.4f from the last vertex: transverse error from "
                      "the chief ray at %.2f nm; tangential e_y(py), sagittal e_x(px)\n",
                      r.image_z - system.last_vertex(), r.primary_nm);
    }
    std::string out = line;
    for (const FieldFans& f : r.fields) {
        std::snprintf(line, sizeof line, "  field %.4g\n  %7s", f.field, "pupil");
        out += line;
        for (const char* kind : {opd ? "W_t" : "e_y", opd ? "W_s" : "e_x"}) {
            for (const RayFan& fan : f.fans) {
                std::snprintf(line, sizeof line, " %4s %6.1f", kind, fan.wavelength_nm);
                out += line;
            }
        }
        out += "\n";
        for (size_t i = 0; i < r.pupil.size(); ++i) {
            std::snprintf(line, sizeof line, "  %7.3f", r.pupil[i]);
            out += line;
            for (const RayFan& fan : f.fans) out += table_cell(fan.tangential[i], 12);
            for (const RayFan& fan : f.fans) out += table_cell(fan.sagittal[i], 12);
            out += "\n";
        }
    }
    return out;
}

}  // namespace lenslab
