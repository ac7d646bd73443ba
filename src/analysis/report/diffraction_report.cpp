#include "analysis/report/diffraction_report.h"

#include <cstdio>

#include "util/format_number.h"

namespace lenslab {

namespace {}  // namespace

namespace {

nlohmann::ordered_json field_psf_json(const FieldPsf& f) {
    nlohmann::ordered_json j;
    j["field"] = f.field;
    if (!f.error.empty()) {
        j["error"] = f.error;
        return j;
    }
    const Psf& p = f.psf;
    j["strehl"] = p.strehl;
    j["strehl_per_wavelength"] = f.strehl_per_wavelength;
    j["centre"] = {f.centre_x, f.centre_y};
    j["centroid"] = {f.centroid_x, f.centroid_y};
    j["encircled_energy"] = {{"radii", f.radii}, {"fraction", f.encircled}};
    j["ensquared_energy"] = {{"half_widths", f.radii}, {"fraction", f.ensquared}};
    j["pupil_samples"] = f.samples;
    j["max_step_waves"] = f.max_step_waves;
    if (!f.warning.empty()) j["warning"] = f.warning;
    j["grid"] = {{"size", p.size}, {"spacing", p.spacing}};
    // Row by row, y rising from -size/2 · spacing about the centre.
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (int i = 0; i < p.size; ++i) {
        nlohmann::ordered_json row = nlohmann::ordered_json::array();
        for (int k = 0; k < p.size; ++k) row.push_back(p.at(i, k));
        rows.push_back(std::move(row));
    }
    j["image"] = std::move(rows);
    return j;
}

// A field's MTF curves and sampling, or why it was not measured; its warning when unresolved.
nlohmann::ordered_json field_mtf_json(const FieldMtf& f) {
    nlohmann::ordered_json field;
    field["field"] = f.field;
    if (!f.error.empty()) {
        field["error"] = f.error;
        return field;
    }
    field["tangential"] = f.tangential;
    field["sagittal"] = f.sagittal;
    field["pupil_samples"] = f.samples;
    field["max_step_waves"] = f.max_step_waves;
    if (!f.warning.empty()) field["warning"] = f.warning;
    return field;
}

}  // namespace

nlohmann::ordered_json psf_json(const DiffractionFigures& figures,
                                const std::vector<FieldPsf>& fields) {
    nlohmann::ordered_json j;
    j["strehl"] = figures.strehl;
    j["wavefront_rms_waves"] = figures.wavefront_rms;
    j["airy_radius"] = figures.airy_radius;
    j["encircled_energy_at_airy_radius"] = figures.encircled_energy_at_airy_radius;
    j["sample_spacing"] = figures.psf.spacing;
    j["image_z"] = figures.image_z;
    j["wavelength_nm"] = figures.wavelength_nm;
    j["f_number"] = figures.f_number;
    nlohmann::ordered_json per_field = nlohmann::ordered_json::array();
    for (const FieldPsf& f : fields) per_field.push_back(field_psf_json(f));
    j["fields"] = std::move(per_field);
    return j;
}

nlohmann::ordered_json mtf_json(const DiffractionFigures& figures, const FieldMtfs& mtf) {
    nlohmann::ordered_json j;
    j["frequencies"] = mtf.frequencies;
    j["cutoff"] = figures.psf.cutoff;
    j["diffraction_limit"] = mtf.diffraction_limit;
    nlohmann::ordered_json fields = nlohmann::ordered_json::array();
    for (const FieldMtf& f : mtf.fields) fields.push_back(field_mtf_json(f));
    j["fields"] = fields;
    j["wavelength_nm"] = figures.wavelength_nm;
    j["image_z"] = mtf.image_z;
    return j;
}

std::string diffraction_table(const DiffractionFigures& figures, const std::vector<FieldPsf>* psfs,
                              const FieldMtfs* mtf) {
    std::string out;
    if (psfs) {
        out += printf_text(
            "\nDiffraction on the axis at %.2f nm, F/%.4g, best focus (%.4f behind the first "
            "vertex)\n",
            figures.wavelength_nm, figures.f_number, figures.image_z);
        out += printf_text("  Strehl ratio %.4f   wavefront RMS %.4f waves\n", figures.strehl,
                           figures.wavefront_rms);
        out += printf_text("  Airy radius 1.22 lambda N = %.6f   encircled energy there %.4f\n",
                           figures.airy_radius, figures.encircled_energy_at_airy_radius);
        out +=
            "  PSF per field, polychromatic: Strehl (per wavelength), centroid against the chief "
            "ray, 80% encircled energy radius\n";
        for (const FieldPsf& f : *psfs) {
            if (!f.error.empty()) {
                out += printf_text("  field %-8g not measured: %s\n", f.field, f.error.c_str());
                continue;
            }
            std::string each;
            for (double s : f.strehl_per_wavelength) each += printf_text(" %.4f", s);
            // The first radius holding 80% of the energy (the curve's eighths, interpolated).
            std::string d80 = "beyond the grid";
            for (size_t k = 0; k < f.radii.size(); ++k) {
                if (f.encircled[k] < 0.8) continue;
                const double r0 = k == 0 ? 0.0 : f.radii[k - 1],
                             e0 = k == 0 ? 0.0 : f.encircled[k - 1];
                d80 = printf_text("%.5g",
                                  r0 + (f.radii[k] - r0) * (0.8 - e0) / (f.encircled[k] - e0));
                break;
            }
            out += printf_text("  field %-8g Strehl %.4f (%s)  centroid (%+.5g, %+.5g)  r80 %s\n",
                               f.field, f.psf.strehl, each.c_str() + 1, f.centroid_x - f.centre_x,
                               f.centroid_y - f.centre_y, d80.c_str());
            if (!f.warning.empty()) out += "    " + f.warning + "\n";
        }
    }
    if (mtf) {
        out += printf_text(
            "\nMTF per field (tangential / sagittal), polychromatic, image plane at z = %.6g\n",
            mtf->image_z);
        out += "  cycles/mm  diffraction limit";
        for (const FieldMtf& f : mtf->fields) out += printf_text("   field %-10g", f.field);
        out += "\n";
        for (size_t i = 0; i < mtf->frequencies.size(); ++i) {
            out += printf_text("  %9.2f  %17.4f", mtf->frequencies[i], mtf->diffraction_limit[i]);
            for (const FieldMtf& f : mtf->fields) {
                out += f.error.empty()
                           ? printf_text("   %.4f / %.4f", f.tangential[i], f.sagittal[i])
                           : std::string("   not measured   ");
            }
            out += "\n";
        }
        for (const FieldMtf& f : mtf->fields) {
            if (!f.error.empty())
                out += printf_text("  field %g not measured: %s\n", f.field, f.error.c_str());
            if (!f.warning.empty())
                out += printf_text("  field %g: %s\n", f.field, f.warning.c_str());
        }
    }
    return out;
}

nlohmann::ordered_json through_focus_json(const ThroughFocusMtf& t) {
    nlohmann::ordered_json j;
    j["frequency"] = t.frequency;
    j["image_z"] = t.image_z;
    j["shifts"] = t.shifts;
    nlohmann::ordered_json fields = nlohmann::ordered_json::array();
    for (const FieldMtf& f : t.fields) fields.push_back(field_mtf_json(f));
    j["fields"] = std::move(fields);
    return j;
}

std::string through_focus_table(const ThroughFocusMtf& t) {
    std::string out =
        printf_text("\nMTF at %g cycles/mm through focus (tangential / sagittal), about z = %.6g\n",
                    t.frequency, t.image_z);
    out += "      shift";
    for (const FieldMtf& f : t.fields) out += printf_text("   field %-10g", f.field);
    out += "\n";
    for (size_t n = 0; n < t.shifts.size(); ++n) {
        out += printf_text("  %+9.5f", t.shifts[n]);
        for (const FieldMtf& f : t.fields) {
            out += f.error.empty() ? printf_text("   %.4f / %.4f", f.tangential[n], f.sagittal[n])
                                   : std::string("   not measured   ");
        }
        out += "\n";
    }
    for (const FieldMtf& f : t.fields) {
        if (!f.error.empty())
            out += printf_text("  field %g not measured: %s\n", f.field, f.error.c_str());
        if (!f.warning.empty()) out += printf_text("  field %g: %s\n", f.field, f.warning.c_str());
    }
    return out;
}

}  // namespace lenslab
