#include "analysis/report/lens_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "analysis/report/first_order_report.h"
#include "analysis/system/parabasal.h"
#include "math/constants.h"
#include "util/format_number.h"
#include "util/scene_error.h"

namespace lenslab {

namespace {

// A wavelength with its line name: "587.56 nm (d)".
std::string wavelength_text(double nm) {
    const std::string name = fraunhofer_name(nm);
    return printf_text("%.2f nm", nm) + (name.empty() ? "" : " (" + name + ")");
}

std::string medium_name(const OpticalSystem& system, int element) {
    return element < 0 ? "air" : system.elements[element].glass;
}

std::string shape_kind(const SystemSurface& s) {
    const std::string d = s.shape->describe();
    return d.substr(0, d.find(' '));
}

// A length to 4 significant figures or so, in a fixed-width column.
std::string length(double v) {
    if (std::abs(v) >= 1e4 || (v != 0 && std::abs(v) < 1e-3)) return printf_text("%.4g", v);
    return printf_text("%.4f", v);
}

// A GRIN lens's profile and, for a radial one, its pitch: the period 2 pi / sqrt(A) of a
// paraxial ray's oscillation, and the lens's length in pitches (1/4: a collimated beam
// focuses on the back face).
nlohmann::ordered_json grin_json(const OpticalSystem& system, const SystemElement& e) {
    const GrinProfile& g = *e.grin;
    const double rod = system.surfaces[e.last_surface].z - system.surfaces[e.first_surface].z;
    nlohmann::ordered_json j = {
        {"profile", grin_kind_name(g.kind)}, {"n0", g.n0}, {"A", g.A}, {"length", rod}};
    if (g.kind == GrinKind::Radial && g.A > 0) {
        const double pitch = 2.0 * kPi / std::sqrt(g.A);
        j["pitch"] = pitch;
        j["pitches"] = rod / pitch;
    }
    return j;
}

}  // namespace

std::string fraunhofer_name(double nm) {
    if (std::abs(nm - kLineD) < 0.01) return "d line";
    if (std::abs(nm - kLineF) < 0.01) return "F line";
    if (std::abs(nm - kLineC) < 0.01) return "C line";
    return "";
}

LensReport analyze_lens_system(const OpticalSystem& system, const LensReportOptions& options) {
    check_wavelength(system, options.wavelength_nm,
                     options.wavelengths.empty() ? "--wavelength" : "--wavelengths");
    LensReport r;
    r.wavelength_nm = options.wavelength_nm;
    r.wavelengths = options.wavelengths.empty() ? std::vector<double>{options.wavelength_nm}
                                                : options.wavelengths;
    for (double nm : r.wavelengths) check_wavelength(system, nm, "--wavelengths");
    if (r.wavelengths.size() >= 2) {
        r.short_nm = *std::min_element(r.wavelengths.begin(), r.wavelengths.end());
        r.long_nm = *std::max_element(r.wavelengths.begin(), r.wavelengths.end());
    } else {
        // The default F/C pair is the report's addition, not the user's request: a glass
        // without data there leaves the colour out rather than refusing the lens.
        try {
            check_wavelength(system, kLineF, "the F line");
            check_wavelength(system, kLineC, "the C line");
        } catch (const SceneError& e) {
            r.chromatic_unavailable = e.path() + ": " + e.reason();
            r.short_nm = r.long_nm = options.wavelength_nm;
        }
    }
    r.paraxial = paraxial_trace(system, options.wavelength_nm);
    r.paraxial_F = paraxial_trace(system, r.short_nm);
    r.paraxial_C = paraxial_trace(system, r.long_nm);
    r.chromatic_shift_FC = r.paraxial_F.bfl - r.paraxial_C.bfl;

    const double usable = usable_aperture_radius(system, options.wavelength_nm);
    r.aperture_radius = options.aperture_radius > 0 ? options.aperture_radius : usable;
    FirstOrderOptions first = options.first_order;
    first.wavelength_nm = options.wavelength_nm;
    if (first.epd <= 0 && first.f_number <= 0 && first.stop == 0) {
        first.epd = 2.0 * r.aperture_radius;
    }
    r.first_order = first_order(system, r.paraxial, first);
    if (r.first_order.parabasal) {
        // A decentred or tilted system: every focal figure about its central chief ray.
        r.paraxial = *r.first_order.parabasal;
        const auto about_chief = [&](double nm) {
            const auto m = parabasal_matrices(system, r.paraxial.reference, nm);
            if (!m)
                throw SceneError("objects",
                                 "the central chief ray does not pass at " + wavelength_text(nm));
            return parabasal_paraxial(system, *m, nm);
        };
        r.paraxial_F = about_chief(r.short_nm);
        r.paraxial_C = about_chief(r.long_nm);
        r.chromatic_shift_FC = r.paraxial_F.bfl - r.paraxial_C.bfl;
    }
    // Seidel sums count surfaces alone; a gradient index adds transfer terms (Sands 1970)
    // that are not modelled, so a GRIN system gets none; nor does a system that is not
    // rotationally symmetric (its aberrations are not the five of a coaxial one).
    if (options.parts.seidel && !system.has_grin() && system.coaxial())
        r.seidel = seidel_sums(system, r.first_order, r.short_nm, r.long_nm);
    if (options.parts.real_chief) r.real_chief = trace_real_chief_ray(system, r.first_order);
    // The axial beam fills the entrance pupil, as far as the lenses let it through.
    if (options.aperture_radius <= 0) {
        r.aperture_radius = std::min(usable, 0.5 * r.first_order.entrance_pupil.diameter);
    }

    if (options.parts.beam) {
        const std::vector<ExitRay> rays = trace_collimated_beam(
            system, options.wavelength_nm, r.aperture_radius, options.spot_rings, &r.rays_lost);
        r.rays = static_cast<int>(rays.size()) + r.rays_lost;
        if (options.parts.paraxial_spot) r.spot_paraxial = spot_at(rays, r.paraxial.z_rear_focus);
        r.spot_best = spot_at(rays, best_focus_z(rays, r.paraxial.z_rear_focus));
        r.best_focus = r.spot_best.z - system.last_vertex();
    }
    if (options.parts.lsa && system.coaxial()) {
        r.lsa = longitudinal_spherical_aberration(system, r.paraxial, r.aperture_radius,
                                                  options.lsa_samples);
    }
    return r;
}

namespace {

using Json = nlohmann::ordered_json;

// One top-level key of report_json's document: what of the report it needs, and its value.
struct ReportKey {
    const char* name;
    LensReportParts needs;
    Json (*value)(const OpticalSystem& system, const LensReport& r);
};

constexpr LensReportParts kNeedsNoPart{false, false, false, false, false};
constexpr LensReportParts kNeedsBeam{true, false, false, false, false};
constexpr LensReportParts kNeedsLsa{false, true, false, false, false};
constexpr LensReportParts kNeedsSeidel{false, false, true, false, false};
constexpr LensReportParts kNeedsRealChief{false, false, false, true, false};
constexpr LensReportParts kNeedsParaxialSpot{true, false, false, false, true};

Json surfaces_json(const OpticalSystem& system, const LensReport& r) {
    Json surfaces = Json::array();
    for (size_t i = 0; i < system.surfaces.size(); ++i) {
        const SystemSurface& s = system.surfaces[i];
        surfaces.push_back({{"surface", s.label},
                            {"shape", s.shape->describe()},
                            {"z", s.z},
                            {"radius", s.curvature == 0 ? Json() : Json(1.0 / s.curvature)},
                            {"semi_diameter", s.semi_diameter},
                            {"medium_after", medium_name(system, s.element_after)},
                            {"n_after", system.n_after(i, r.wavelength_nm)}});
        if (s.mirror) {
            surfaces.back()["mirror"] = true;
            surfaces.back()["hole_semi_diameter"] = s.hole_semi_diameter;
        }
    }
    return surfaces;
}

Json lenses_json(const OpticalSystem& system) {
    Json lenses = Json::array();
    for (const SystemElement& e : system.elements) {
        Json lens = {{"object", e.path}, {"name", e.name}, {"glass", e.glass}};
        if (e.grin) lens["grin"] = grin_json(system, e);
        lenses.push_back(lens);
    }
    return lenses;
}

Json lsa_json(const LensReport& r) {
    Json lsa = Json::array();
    for (const LsaPoint& p : r.lsa) {
        lsa.push_back({{"height", p.height}, {"lsa", p.lsa}, {"transverse", p.transverse}});
    }
    return lsa;
}

Json first_order_with_chief_json(const OpticalSystem& system, const LensReport& r) {
    Json first = first_order_json(system, r.first_order);
    first["real_chief_ray"] = r.real_chief ? Json{{"image_height", r.real_chief->image_height},
                                                  {"distortion", r.real_chief->distortion}}
                                           : Json();
    return first;
}

// The document's keys in its order.
const ReportKey kReportKeys[] = {
    {"wavelength_nm", kNeedsNoPart,
     [](const OpticalSystem&, const LensReport& r) { return Json(r.wavelength_nm); }},
    {"length_unit", kNeedsNoPart,
     [](const OpticalSystem&, const LensReport&) {
         return Json("scene unit (mm for lens prescriptions)");
     }},
    {"efl", kNeedsNoPart,
     [](const OpticalSystem&, const LensReport& r) { return Json(r.paraxial.efl); }},
    {"first_order_basis", kNeedsNoPart,
     [](const OpticalSystem&, const LensReport& r) {
         return Json(r.paraxial.parabasal ? "parabasal" : "paraxial");
     }},
    {"efl_x", kNeedsNoPart,
     [](const OpticalSystem&, const LensReport& r) {
         return r.paraxial.parabasal ? Json(r.paraxial.efl_x) : Json(r.paraxial.efl);
     }},
    {"bfl", kNeedsNoPart,
     [](const OpticalSystem&, const LensReport& r) { return Json(r.paraxial.bfl); }},
    {"ffl", kNeedsNoPart,
     [](const OpticalSystem&, const LensReport& r) { return Json(r.paraxial.ffl); }},
    {"power", kNeedsNoPart,
     [](const OpticalSystem&, const LensReport& r) { return Json(r.paraxial.power); }},
    {"principal_planes", kNeedsNoPart,
     [](const OpticalSystem& system, const LensReport& r) {
         return Json{{"front", r.paraxial.z_front_principal},
                     {"back", r.paraxial.z_rear_principal - system.last_vertex()},
                     {"note", "front: from the first vertex; back: from the last vertex"}};
     }},
    {"aperture_diameter", kNeedsNoPart,
     [](const OpticalSystem&, const LensReport& r) { return Json(2.0 * r.aperture_radius); }},
    {"rays", kNeedsBeam, [](const OpticalSystem&, const LensReport& r) { return Json(r.rays); }},
    {"rays_lost", kNeedsBeam,
     [](const OpticalSystem&, const LensReport& r) { return Json(r.rays_lost); }},
    {"rms_spot_paraxial", kNeedsParaxialSpot,
     [](const OpticalSystem&, const LensReport& r) { return Json(r.spot_paraxial.rms_radius); }},
    {"geometric_spot_paraxial", kNeedsParaxialSpot,
     [](const OpticalSystem&, const LensReport& r) {
         return Json(r.spot_paraxial.geometric_radius);
     }},
    {"best_focus", kNeedsBeam,
     [](const OpticalSystem&, const LensReport& r) { return Json(r.best_focus); }},
    {"best_focus_shift", kNeedsBeam,
     [](const OpticalSystem&, const LensReport& r) {
         return Json(r.spot_best.z - r.paraxial.z_rear_focus);
     }},
    {"rms_spot_best", kNeedsBeam,
     [](const OpticalSystem&, const LensReport& r) { return Json(r.spot_best.rms_radius); }},
    {"geometric_spot_best", kNeedsBeam,
     [](const OpticalSystem&, const LensReport& r) { return Json(r.spot_best.geometric_radius); }},
    {"chromatic_shift_FC", kNeedsNoPart,
     [](const OpticalSystem&, const LensReport& r) {
         return r.chromatic_unavailable.empty() ? Json(r.chromatic_shift_FC) : Json();
     }},
    {"wavelengths_nm", kNeedsNoPart,
     [](const OpticalSystem&, const LensReport& r) { return Json(r.wavelengths); }},
    {"chromatic", kNeedsNoPart,
     [](const OpticalSystem&, const LensReport& r) {
         if (!r.chromatic_unavailable.empty())
             return Json{{"unavailable", r.chromatic_unavailable}};
         return Json{{"wavelengths_nm", {r.short_nm, r.long_nm}},
                     {"bfl_F", r.paraxial_F.bfl},
                     {"bfl_C", r.paraxial_C.bfl},
                     {"efl_F", r.paraxial_F.efl},
                     {"efl_C", r.paraxial_C.efl}};
     }},
    {"lsa", kNeedsLsa, [](const OpticalSystem&, const LensReport& r) { return lsa_json(r); }},
    {"surfaces", kNeedsNoPart, &surfaces_json},
    {"lenses", kNeedsNoPart,
     [](const OpticalSystem& system, const LensReport&) { return lenses_json(system); }},
    {"ignored", kNeedsNoPart,
     [](const OpticalSystem& system, const LensReport&) { return Json(system.ignored); }},
    {"first_order", kNeedsRealChief, &first_order_with_chief_json},
    {"seidel", kNeedsSeidel,
     [](const OpticalSystem& system, const LensReport& r) {
         return system.has_grin() || !system.coaxial() ? Json() : seidel_json(system, r.seidel);
     }},
};

bool asked_for(const std::vector<std::string>& keys, const char* key) {
    return keys.empty() || std::find(keys.begin(), keys.end(), key) != keys.end();
}

}  // namespace

nlohmann::ordered_json report_json(const OpticalSystem& system, const LensReport& r,
                                   const std::vector<std::string>& keys) {
    Json j = Json::object();
    for (const ReportKey& key : kReportKeys) {
        if (asked_for(keys, key.name)) j[key.name] = key.value(system, r);
    }
    return j;
}

std::vector<std::string> report_json_keys() {
    std::vector<std::string> out;
    for (const ReportKey& key : kReportKeys) out.emplace_back(key.name);
    return out;
}

LensReportParts report_parts(const std::vector<std::string>& keys) {
    if (keys.empty()) return {};
    LensReportParts parts = kNeedsNoPart;
    for (const ReportKey& key : kReportKeys) {
        if (!asked_for(keys, key.name)) continue;
        parts.beam = parts.beam || key.needs.beam;
        parts.lsa = parts.lsa || key.needs.lsa;
        parts.seidel = parts.seidel || key.needs.seidel;
        parts.real_chief = parts.real_chief || key.needs.real_chief;
        parts.paraxial_spot = parts.paraxial_spot || key.needs.paraxial_spot;
    }
    return parts;
}

std::string report_table(const OpticalSystem& system, const LensReport& r, bool seidel) {
    std::ostringstream out;
    const ParaxialResult& p = r.paraxial;
    const double last = system.last_vertex();
    const auto mirrors = std::count_if(system.surfaces.begin(), system.surfaces.end(),
                                       [](const SystemSurface& s) { return s.mirror; });
    out << system.elements.size() << (system.elements.size() == 1 ? " lens, " : " lenses, ");
    if (mirrors > 0) out << mirrors << (mirrors == 1 ? " mirror, " : " mirrors, ");
    out << system.surfaces.size()
        << (system.coaxial() ? " surfaces on one axis"
                             : " surfaces about one axis, some decentred, tilted or anamorphic")
        << "; lengths in the scene's unit "
        << "(mm for lens prescriptions), light travelling along +z from the first vertex"
        << (system.folded() ? " and turning back at each mirror (indices signed by the way "
                              "light travels)"
                            : "")
        << "\n\n";
    char line[256];
    std::snprintf(line, sizeof line, "  %-36s %-8s %10s %11s %10s  %s\n", "surface", "shape", "z",
                  "R (vertex)", "semi-diam", "medium after");
    out << line;
    for (const SystemSurface& s : system.surfaces) {
        std::snprintf(line, sizeof line, "  %-36s %-8s %10s %11s %10s  %s\n", s.label.c_str(),
                      shape_kind(s).c_str(), length(s.z).c_str(),
                      s.curvature == 0 ? "flat" : length(1.0 / s.curvature).c_str(),
                      length(s.semi_diameter).c_str(),
                      s.mirror ? "(mirror)" : medium_name(system, s.element_after).c_str());
        out << line;
    }
    for (const std::string& ignored : system.ignored) out << "  ignored: " << ignored << "\n";

    const auto row = [&](const std::string& what, double v, const std::string& note = "") {
        std::snprintf(line, sizeof line, "  %-34s %12s", what.c_str(), length(v).c_str());
        out << line << (note.empty() ? "" : "  " + note) << "\n";
    };
    if (p.parabasal) {
        out << "\nParabasal (about the real chief ray of the central field: decentred, tilted "
               "or anamorphic surfaces), at "
            << wavelength_text(r.wavelength_nm) << "\n";
        row("EFL in the x-z section", p.efl_x);
    } else {
        out << "\nParaxial, at " << wavelength_text(r.wavelength_nm) << "\n";
    }
    row("effective focal length EFL", p.efl);
    row("back focal length BFL", p.bfl, "last vertex to the rear focal point F'");
    row("front focal length FFL", p.ffl, "front focal point F to the first vertex");
    row("front principal plane H", p.z_front_principal, "from the first vertex");
    row("rear principal plane H'", p.z_rear_principal - last, "from the last vertex");

    out << "\nReal rays, at " << wavelength_text(r.wavelength_nm)
        << ": collimated beam on the axis, diameter " << length(2.0 * r.aperture_radius) << ", "
        << r.rays << " rays";
    if (r.rays_lost > 0) out << " (" << r.rays_lost << " clipped or totally reflected)";
    // A pupil wider than the lenses pass: the beam is what passes, so say so.
    if (r.first_order.entrance_pupil.diameter > 2.0 * r.aperture_radius * (1.0 + 1e-9)) {
        out << " (narrower than the entrance pupil, "
            << length(r.first_order.entrance_pupil.diameter) << ": the lenses pass no more)";
    }
    out << "\n";
    row("RMS spot radius at the paraxial focus", r.spot_paraxial.rms_radius,
        "geometric radius " + length(r.spot_paraxial.geometric_radius));
    row("best focus (least RMS spot)", r.best_focus,
        "from the last vertex; " + length(r.spot_best.z - p.z_rear_focus) +
            " from the paraxial focus");
    row("RMS spot radius at the best focus", r.spot_best.rms_radius,
        "geometric radius " + length(r.spot_best.geometric_radius));
    if (!system.coaxial()) {
        out << "  longitudinal spherical aberration: not for a decentred, tilted or anamorphic "
               "system\n";
    } else {
        out << "  longitudinal spherical aberration (axis crossing minus paraxial focus; < 0: in "
               "front):\n";
        std::snprintf(line, sizeof line, "    %12s %12s %14s\n", "ray height", "LSA", "transverse");
        out << line;
    }
    const size_t step = std::max<size_t>(1, r.lsa.size() / 10);
    for (size_t i = 0; i < r.lsa.size(); ++i) {
        if ((i + 1) % step != 0 && i + 1 != r.lsa.size()) continue;
        const LsaPoint& q = r.lsa[i];
        std::snprintf(line, sizeof line, "    %12s %12s %14s\n", length(q.height).c_str(),
                      length(q.lsa).c_str(), length(q.transverse).c_str());
        out << line;
    }

    const bool fc = r.short_nm == kLineF && r.long_nm == kLineC;
    if (!r.chromatic_unavailable.empty()) {
        out << "\nChromatic (paraxial): unavailable, " << r.chromatic_unavailable << "\n";
    } else {
        out << "\nChromatic (paraxial), " << (fc ? "F = " : "short ") << wavelength_text(r.short_nm)
            << (fc ? ", C = " : ", long ") << wavelength_text(r.long_nm) << "\n";
        row(fc ? "BFL at the F line" : "BFL at the short wavelength", r.paraxial_F.bfl);
        row(fc ? "BFL at the C line" : "BFL at the long wavelength", r.paraxial_C.bfl);
        row(fc ? "focal shift BFL(F) - BFL(C)" : "focal shift BFL(short) - BFL(long)",
            r.chromatic_shift_FC);
    }
    out << "\n" << first_order_table(system, r.first_order);
    if (r.real_chief && r.first_order.field != 0.0) {
        row("real chief ray image height", r.real_chief->image_height,
            "distortion " + printf_text("%.6f", 100.0 * r.real_chief->distortion) + " %");
    }
    if (seidel && system.has_grin()) {
        out << "\nSeidel sums: not computed for gradient-index lenses (their transfer terms are "
               "not modelled)\n";
    } else if (seidel && !system.coaxial()) {
        out << "\nSeidel sums: not computed for a decentred, tilted or anamorphic system (not "
               "rotationally "
               "symmetric); see its spots, fans and --field-map\n";
    } else if (seidel) {
        out << "\n" << seidel_table(system, r.seidel);
    }
    return out.str();
}

}  // namespace lenslab
