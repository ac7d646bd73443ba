#include "lensfile/prescription_surface.h"

#include <cmath>
#include <cstdio>

#include "util/format_number.h"

namespace lenslab {

using nlohmann::ordered_json;

std::string prescription_surface_label(size_t i) { return "surface " + std::to_string(i); }

namespace {

// [A4, A6, ...] in millimetres from the file's r^2, r^4, ... terms: the r^(2m) term
// scales as length^(1 - 2m).
ordered_json coefficients_mm(const std::vector<double>& terms, double mm) {
    ordered_json coefficients = ordered_json::array();
    for (size_t m = 1; m < terms.size(); ++m) {
        coefficients.push_back(terms[m] * std::pow(mm, 1.0 - 2.0 * (m + 1)));
    }
    return coefficients;
}

// A Zernike sag or an XY polynomial: XDAT 1 the number of terms, 2 the normalisation
// radius, 3 ... the terms (lengths: scaled to mm, as the radius).
ordered_json polynomial_json(const LensFileSurface& s, const std::vector<double>& terms, double mm,
                             const std::string& file) {
    const bool zernike = s.anamorphic == "zernike";
    const int line = s.extra_data_line ? s.extra_data_line : s.line;
    const std::vector<double>& x = s.extra_data;
    const double count = x.empty() ? 0.0 : x[0];
    const double most = zernike ? 231 : 230;
    if (!(count >= 1 && count <= most) || count != std::floor(count)) {
        throw LensFileError(file, line,
                            "XDAT 1, the number of terms, must be a whole number from 1 to " +
                                format_number(most) + ", got " + format_number(count));
    }
    if (x.size() < 2 || !(x[1] > 0)) {
        throw LensFileError(file, line,
                            "XDAT 2, the normalisation radius, must be > 0, got " +
                                format_number(x.size() < 2 ? 0.0 : x[1]));
    }
    ordered_json list = ordered_json::array();
    for (size_t j = 0; j < size_t(count); ++j)
        list.push_back(2 + j < x.size() ? x[2 + j] * mm : 0.0);
    ordered_json out = {{"shape", zernike ? "zernike" : "xy_polynomial"},
                        {"radius", s.radius * mm},
                        {"k", s.conic}};
    if (terms.size() > 1) out["coefficients"] = coefficients_mm(terms, mm);
    out["normalization_radius"] = x[1] * mm;
    out[zernike ? "zernike" : "terms"] = list;
    return out;
}

// A face not of revolution (terms: the even ones of a toroid's y curve or a Zernike sag's
// base, without an r^2 term).
ordered_json anamorphic_json(const LensFileSurface& s, const std::vector<double>& terms, double mm,
                             const std::string& file) {
    if (s.anamorphic == "biconic") {
        return {{"shape", "biconic"},
                {"radius_x", s.radius_x * mm},
                {"radius_y", s.radius * mm},
                {"k_x", s.conic_x},
                {"k_y", s.conic}};
    }
    if (s.anamorphic == "zernike" || s.anamorphic == "xy_polynomial") {
        return polynomial_json(s, terms, mm, file);
    }
    ordered_json toroid = {{"shape", "toroidal"}, {"radius", s.radius * mm}, {"k", s.conic}};
    if (terms.size() > 1) toroid["coefficients"] = coefficients_mm(terms, mm);
    toroid["radius_of_rotation"] = s.radius_of_rotation * mm;
    return toroid;
}

}  // namespace

// A face must exist out to the element's semi-diameter: |R| / sqrt(1 + k) for a conic.
void check_prescription_span(const LensFilePrescription& p, size_t i, double sd) {
    const LensFileSurface& s = p.surfaces[i];
    const double mm = p.unit_mm;
    if (s.radius == 0.0) return;
    const double r = std::abs(s.radius) * mm;
    const double widest = 1.0 + s.conic > 0.0 ? r / std::sqrt(1.0 + s.conic) : INFINITY;
    if (sd > widest * (1.0 + 1e-12)) {
        throw LensFileError(p.file, s.radius_line ? s.radius_line : s.line,
                            prescription_surface_label(i) + ": radius " +
                                format_number(s.radius * mm) +
                                (s.conic != 0.0 ? " with conic " + format_number(s.conic) : "") +
                                " mm is undefined beyond " + format_number(widest) +
                                " mm from the axis, inside its element's semi-diameter " +
                                format_number(sd) + " mm");
    }
}

ordered_json prescription_surface_json(const LensFilePrescription& p, size_t i) {
    const LensFileSurface& s = p.surfaces[i];
    const double mm = p.unit_mm;
    const auto refuse = [&](int line, const std::string& reason) {
        throw LensFileError(p.file, line, reason);
    };
    std::vector<double> terms = s.even_terms;
    while (!terms.empty() && terms.back() == 0.0) terms.pop_back();
    if (!terms.empty() && terms[0] != 0.0) {
        refuse(s.line, prescription_surface_label(i) +
                           ": an aspheric r^2 term; lenslab's asphere starts at r^4 (fold "
                           "it into the curvature)");
    }
    if (terms.size() > 8) {
        refuse(s.line, prescription_surface_label(i) +
                           ": aspheric terms beyond r^16 cannot be represented");
    }
    if (!s.anamorphic.empty()) return anamorphic_json(s, terms, mm, p.file);
    if (s.radius == 0.0) {
        if (terms.empty()) return {{"shape", "flat"}};
        // A flat base with aspheric terms (a Schmidt plate's): lenslab's asphere needs a
        // vertex radius, a sag formula in r does not.
        std::string formula;
        for (size_t m = 1; m < terms.size(); ++m) {
            if (terms[m] == 0.0) continue;
            char term[64];
            std::snprintf(term, sizeof term, "%s(%.17g)*r^%zu", formula.empty() ? "" : " + ",
                          terms[m] * std::pow(mm, 1.0 - 2.0 * (m + 1)), 2 * (m + 1));
            formula += term;
        }
        return {{"shape", "sag"}, {"formula", formula}};
    }
    const double radius = s.radius * mm;
    if (terms.empty()) {
        if (s.conic == 0.0) return {{"shape", "sphere"}, {"radius", radius}};
        return {{"shape", "conic"}, {"radius", radius}, {"k", s.conic}};
    }
    return {{"shape", "asphere"},
            {"radius", radius},
            {"k", s.conic},
            {"coefficients", coefficients_mm(terms, mm)}};
}

}  // namespace lenslab
