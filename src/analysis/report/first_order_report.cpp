#include "analysis/report/first_order_report.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace lenslab {

namespace {

// JSON has no infinity: a pupil or image at infinity is null.
nlohmann::ordered_json finite_or_null(double v) {
    return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json();
}

// The colour sums are null when there was no pair of wavelengths to take them between.
nlohmann::ordered_json sums_json(const SeidelSums& s, bool colour) {
    using nlohmann::ordered_json;
    return {{"S_I", s.spherical},
            {"S_II", s.coma},
            {"S_III", s.astigmatism},
            {"S_IV", s.petzval},
            {"S_V", s.distortion},
            {"C_I", colour ? ordered_json(s.axial_colour) : ordered_json()},
            {"C_II", colour ? ordered_json(s.lateral_colour) : ordered_json()}};
}

std::string number_text(double v) {
    if (!std::isfinite(v)) return v > 0 ? "infinity" : "-infinity";
    char buffer[64];
    if (v != 0 && (std::abs(v) >= 1e5 || std::abs(v) < 1e-4)) {
        std::snprintf(buffer, sizeof buffer, "%.4e", v);
    } else {
        std::snprintf(buffer, sizeof buffer, "%.6f", v);
    }
    return buffer;
}

}  // namespace

nlohmann::ordered_json first_order_json(const OpticalSystem& system, const FirstOrder& f) {
    using nlohmann::ordered_json;
    ordered_json rays = ordered_json::array();
    for (size_t i = 0; i < system.surfaces.size(); ++i) {
        const ParaxialRaySurface& m = f.marginal.surfaces[i];
        const ParaxialRaySurface& c = f.chief.surfaces[i];
        rays.push_back({{"surface", i + 1},
                        {"y", m.y},
                        {"nu", m.n_after * m.u_after},
                        {"y_chief", c.y},
                        {"nu_chief", c.n_after * c.u_after}});
    }
    return {
        {"wavelength_nm", f.wavelength_nm},
        {"basis", f.parabasal ? "parabasal" : "paraxial"},
        {"efl", f.efl},
        {"bfl", f.bfl},
        {"f_number", f.f_number},
        {"working_f_number", f.working_f_number},
        {"na", f.na},
        {"entrance_pupil",
         {{"position", finite_or_null(f.entrance_pupil.position)},
          {"diameter", f.entrance_pupil.diameter}}},
        {"exit_pupil",
         {{"position", finite_or_null(f.exit_pupil.position)},
          {"diameter", finite_or_null(f.exit_pupil.diameter)}}},
        {"lagrange_invariant", f.lagrange_invariant},
        {"magnification", f.magnification ? ordered_json(*f.magnification) : ordered_json()},
        {"stop",
         {{"surface", f.stop + 1},
          {"label", system.surfaces[f.stop].label},
          {"semi_diameter", f.stop_semi_diameter}}},
        {"field", f.field},
        {"ray_aiming", ray_aiming_name(f.ray_aiming)},
        {"image",
         {{"position", finite_or_null(f.image_position)},
          {"height", finite_or_null(f.image_height)}}},
        {"rays", rays},
        {"note",
         "entrance pupil position from the first vertex, exit pupil and image from the last, "
         "> 0 behind the vertex; H = n (u_chief y - u y_chief) in object space; nu after "
         "each surface's refraction; the chief ray from the largest field"},
    };
}

nlohmann::ordered_json seidel_json(const OpticalSystem& system, const Seidel& s) {
    using nlohmann::ordered_json;
    const bool colour = s.short_nm != s.long_nm;
    const auto colour_or_null = [&](double v) { return colour ? ordered_json(v) : ordered_json(); };
    ordered_json surfaces = ordered_json::array();
    for (size_t i = 0; i < s.surfaces.size(); ++i) {
        ordered_json j = {{"surface", i + 1}, {"label", system.surfaces[i].label}};
        j.update(sums_json(s.surfaces[i], colour));
        surfaces.push_back(j);
    }
    const SeidelTransverse& t = s.transverse;
    return {
        {"wavelengths_nm", {s.short_nm, s.long_nm}},
        {"surfaces", surfaces},
        {"total", sums_json(s.total, colour)},
        {"transverse",
         {{"spherical", t.spherical},
          {"sagittal_coma", t.sagittal_coma},
          {"tangential_coma", t.tangential_coma},
          {"tangential_field", t.tangential_field},
          {"sagittal_field", t.sagittal_field},
          {"petzval", t.petzval},
          {"distortion", t.distortion},
          {"axial_colour", colour_or_null(t.axial_colour)},
          {"lateral_colour", colour_or_null(t.lateral_colour)},
          {"longitudinal_axial_colour", colour_or_null(t.longitudinal_axial_colour)}}},
    };
}

std::string first_order_table(const OpticalSystem& system, const FirstOrder& f) {
    std::ostringstream out;
    char line[256];
    const auto row = [&](const char* what, double v, const std::string& note = "") {
        std::snprintf(line, sizeof line, "  %-34s %14s", what, number_text(v).c_str());
        out << line << (note.empty() ? "" : "  " + note) << "\n";
    };
    out << (f.parabasal ? "First order (parabasal: EFL, F-numbers, NA, image; the pupils and the "
                          "rays below as designed, on the axis)"
                        : "First order (paraxial)")
        << ", stop at surface " << f.stop + 1 << " (" << system.surfaces[f.stop].label
        << "); real rays aimed "
        << (f.ray_aiming == RayAiming::Paraxial ? "at the paraxial entrance pupil"
                                                : "through the stop")
        << "\n";
    row("entrance pupil position", f.entrance_pupil.position, "from the first vertex");
    row("entrance pupil diameter", f.entrance_pupil.diameter);
    row("exit pupil position", f.exit_pupil.position, "from the last vertex");
    row("exit pupil diameter", f.exit_pupil.diameter);
    row("F-number", f.f_number, "EFL / entrance pupil diameter");
    row("working F-number", f.working_f_number, "1 / (2 n' |u'|)");
    row("image-space NA", f.na, "n' |u'|");
    row("Lagrange invariant H", f.lagrange_invariant, "n (u_chief y - u y_chief)");
    if (f.magnification) row("magnification", *f.magnification);
    row("paraxial image", f.image_position, "from the last vertex");
    row("paraxial image height", f.image_height);
    std::snprintf(line, sizeof line, "  %7s %14s %14s %14s %14s\n", "surface", "y", "nu", "y chief",
                  "nu chief");
    out << line;
    for (size_t i = 0; i < system.surfaces.size(); ++i) {
        const ParaxialRaySurface& m = f.marginal.surfaces[i];
        const ParaxialRaySurface& c = f.chief.surfaces[i];
        std::snprintf(line, sizeof line, "  %7zu %14s %14s %14s %14s\n", i + 1,
                      number_text(m.y).c_str(), number_text(m.n_after * m.u_after).c_str(),
                      number_text(c.y).c_str(), number_text(c.n_after * c.u_after).c_str());
        out << line;
    }
    return out.str();
}

std::string seidel_table(const OpticalSystem& system, const Seidel& s) {
    std::ostringstream out;
    char line[256];
    char colour[96];
    std::snprintf(colour, sizeof colour, "%.2f and %.2f nm", s.short_nm, s.long_nm);
    out << "Seidel sums (wavefront units; colour between " << colour << ")\n";
    std::snprintf(line, sizeof line, "  %7s %12s %12s %12s %12s %12s %12s %12s\n", "surface", "S_I",
                  "S_II", "S_III", "S_IV", "S_V", "C_I", "C_II");
    out << line;
    const auto sums_row = [&](const std::string& name, const SeidelSums& v) {
        std::snprintf(line, sizeof line, "  %7s %12.6f %12.6f %12.6f %12.6f %12.6f %12.6f %12.6f\n",
                      name.c_str(), v.spherical, v.coma, v.astigmatism, v.petzval, v.distortion,
                      v.axial_colour, v.lateral_colour);
        out << line;
    };
    for (size_t i = 0; i < s.surfaces.size(); ++i) sums_row(std::to_string(i + 1), s.surfaces[i]);
    sums_row("total", s.total);
    (void)system;
    const SeidelTransverse& t = s.transverse;
    out << "  transverse, in the paraxial image plane:\n";
    const auto row = [&](const char* what, double v) {
        std::snprintf(line, sizeof line, "    %-32s %14s\n", what, number_text(v).c_str());
        out << line;
    };
    row("spherical", t.spherical);
    row("sagittal coma", t.sagittal_coma);
    row("tangential coma", t.tangential_coma);
    row("tangential field", t.tangential_field);
    row("sagittal field", t.sagittal_field);
    row("Petzval", t.petzval);
    row("distortion", t.distortion);
    row("axial colour", t.axial_colour);
    row("lateral colour", t.lateral_colour);
    row("longitudinal axial colour", t.longitudinal_axial_colour);
    return out.str();
}

}  // namespace lenslab
