#include "analysis/report/curve_report.h"

#include <cmath>
#include <cstdio>

#include "analysis/report/report_cells.h"

namespace lenslab {

namespace {

using Json = nlohmann::ordered_json;

template <class Get>
Json curve_column(const FieldCurve& c, Get get) {
    std::vector<double> values;
    for (const FieldCurvePoint& p : c.points) values.push_back(get(p));
    return json_numbers(values);
}

}  // namespace

Json field_curves_json(const OpticalSystem& system, const FieldCurves& r) {
    Json j;
    j["image_z"] = r.image_z;
    j["image_position"] = r.image_z - system.last_vertex();
    j["differential_pupil"] = kFieldCurveDifferentialPupil;
    Json curves = Json::array();
    for (const FieldCurve& c : r.curves) {
        Json e;
        e["wavelength"] = c.wavelength_nm;
        e["fields"] = curve_column(c, [](const FieldCurvePoint& p) { return p.field; });
        e["tangential"] = curve_column(c, [](const FieldCurvePoint& p) { return p.tangential; });
        e["sagittal"] = curve_column(c, [](const FieldCurvePoint& p) { return p.sagittal; });
        e["chief_height"] =
            curve_column(c, [](const FieldCurvePoint& p) { return p.chief_height; });
        e["paraxial_height"] =
            curve_column(c, [](const FieldCurvePoint& p) { return p.paraxial_height; });
        e["distortion"] = curve_column(c, [](const FieldCurvePoint& p) { return p.distortion; });
        curves.push_back(std::move(e));
    }
    j["curves"] = std::move(curves);
    return j;
}

std::string field_curves_table(const OpticalSystem& system, const FieldCurves& r) {
    char line[200];
    std::snprintf(line, sizeof line,
                  "\nField curves (real rays) in the plane %.4f from the last vertex: tangential "
                  "and sagittal focus from that plane (> 0 behind it), real chief ray height, "
                  "distortion\n",
                  r.image_z - system.last_vertex());
    std::string out = line;
    for (const FieldCurve& c : r.curves) {
        std::snprintf(line, sizeof line, "  %.2f nm\n  %10s %11s %11s %11s %11s %11s\n",
                      c.wavelength_nm, "field", "tangential", "sagittal", "chief y", "paraxial y",
                      "distortion %");
        out += line;
        for (const FieldCurvePoint& p : c.points) {
            std::snprintf(line, sizeof line, "  %10.4g", p.field);
            out += line + table_cell(p.tangential, 12) + table_cell(p.sagittal, 12) +
                   table_cell(p.chief_height, 12, 5) + table_cell(p.paraxial_height, 12, 5) +
                   table_cell(100.0 * p.distortion, 12, 5) + "\n";
        }
    }
    return out;
}

Json focal_shift_json(const FocalShift& s) {
    Json j;
    j["reference_wavelength_nm"] = s.reference_nm;
    j["wavelengths"] = s.wavelengths;
    j["shift"] = s.shift;
    return j;
}

std::string focal_shift_table(const FocalShift& s) {
    char line[160];
    std::snprintf(line, sizeof line,
                  "\nChromatic focal shift (paraxial image position minus that at %.2f nm; > 0: "
                  "behind)\n  %10s %12s\n",
                  s.reference_nm, "nm", "shift");
    std::string out = line;
    for (size_t i = 0; i < s.wavelengths.size(); ++i) {
        std::snprintf(line, sizeof line, "  %10.2f %12.6f\n", s.wavelengths[i], s.shift[i]);
        out += line;
    }
    return out;
}

}  // namespace lenslab
