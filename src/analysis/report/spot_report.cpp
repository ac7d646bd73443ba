#include "analysis/report/spot_report.h"

#include <cmath>
#include <cstdio>

#include "analysis/report/report_cells.h"
#include "util/format_number.h"

namespace lenslab {

namespace {

using Json = nlohmann::ordered_json;

Json spot_xy(double x, double y) { return Json{{"x", x}, {"y", y}}; }

}  // namespace

Json spots_json(const OpticalSystem& system, const SpotDiagrams& d) {
    Json j;
    j["image_z"] = d.image_z;
    j["image_position"] = d.image_z - system.last_vertex();
    j["rings"] = d.rings;
    j["rays_per_beam"] = d.rays_per_beam;
    j["reference"] = "centroid";
    j["wavelengths_nm"] = d.wavelengths;
    j["weights"] = d.weights;
    j["primary_wavelength_nm"] = d.primary_nm;
    j["working_f_number"] = d.working_f_number;
    Json per_wavelength = Json::array(), polychromatic = Json::array();
    for (const FieldSpots& f : d.fields) {
        for (const WavelengthSpot& s : f.spots) {
            Json e;
            e["field"] = s.field;
            e["wavelength"] = s.wavelength_nm;
            e["rms_radius"] = json_number(s.spot.rms_radius);
            e["geometric_radius"] = json_number(s.spot.geometric_radius);
            e["centroid"] = s.spot.points.empty() ? Json(nullptr)
                                                  : spot_xy(s.spot.centroid_x, s.spot.centroid_y);
            e["chief"] = s.chief ? spot_xy(s.chief->x, s.chief->y) : Json(nullptr);
            e["rays"] = s.rays;
            e["vignetted"] = s.vignetted;
            e["airy_radius"] = s.airy_radius;
            per_wavelength.push_back(std::move(e));
        }
        const PolychromaticSpot& p = f.polychromatic;
        Json e;
        e["field"] = f.field;
        e["rms_radius"] = json_number(p.rms_radius);
        e["centroid"] =
            std::isnan(p.rms_radius) ? Json(nullptr) : spot_xy(p.centroid_x, p.centroid_y);
        e["rays"] = p.rays;
        e["vignetted"] = p.lost;
        e["airy_radius"] = f.airy_radius;
        polychromatic.push_back(std::move(e));
    }
    j["per_wavelength"] = std::move(per_wavelength);
    j["polychromatic"] = std::move(polychromatic);
    return j;
}

std::string spots_table(const OpticalSystem& system, const SpotDiagrams& d) {
    std::string out = printf_text(
        "\nSpot diagrams in the plane %.4f from the last vertex (z %.4f); hexapolar, %d rings "
        "(%d rays a beam); radii about the centroid; Airy radius 1.22 lambda N_w, N_w %.4g\n",
        d.image_z - system.last_vertex(), d.image_z, d.rings, d.rays_per_beam, d.working_f_number);
    out += printf_text("  %10s %13s %11s %11s %11s %11s %11s %11s %6s %6s %11s\n", "field",
                       "wavelength", "RMS radius", "geom radius", "centroid x", "centroid y",
                       "chief x", "chief y", "rays", "vign.", "Airy radius");
    for (const FieldSpots& f : d.fields) {
        for (const WavelengthSpot& s : f.spots) {
            const bool hit = !s.spot.points.empty();
            out += printf_text("  %10.4g %10.2f nm", s.field, s.wavelength_nm) +
                   table_cell(s.spot.rms_radius, 12) + table_cell(s.spot.geometric_radius, 12) +
                   table_cell(hit ? s.spot.centroid_x : NAN, 12) +
                   table_cell(hit ? s.spot.centroid_y : NAN, 12) +
                   table_cell(s.chief ? s.chief->x : NAN, 12) +
                   table_cell(s.chief ? s.chief->y : NAN, 12) +
                   printf_text(" %6d %6d", s.rays, s.vignetted) + table_cell(s.airy_radius, 12) +
                   "\n";
        }
        const PolychromaticSpot& p = f.polychromatic;
        const bool hit = !std::isnan(p.rms_radius);
        out += printf_text("  %10.4g %13s", f.field, "polychromatic") +
               table_cell(p.rms_radius, 12) + printf_text("%12s", "") +
               table_cell(hit ? p.centroid_x : NAN, 12) + table_cell(hit ? p.centroid_y : NAN, 12) +
               printf_text("%24s", "") + printf_text(" %6d %6d", p.rays, p.lost) +
               table_cell(f.airy_radius, 12) + "\n";
    }
    return out;
}

}  // namespace lenslab
