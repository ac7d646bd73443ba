#include "analysis/report/wavefront_report.h"

#include <cstdio>

#include "util/format_number.h"

namespace lenslab {

namespace {

using nlohmann::ordered_json;

// The pupil's samples × samples square of the padded grid, a row per y from -1 to 1, null
// where no ray passed.
ordered_json opd_map_json(const PupilFunction& p) {
    const int first = p.size / 2 - p.samples / 2;
    ordered_json rows = ordered_json::array();
    for (int i = first; i < first + p.samples; ++i) {
        ordered_json row = ordered_json::array();
        for (int j = first; j < first + p.samples; ++j) {
            const size_t cell = p.index(i, j);
            row.push_back(p.amplitude[cell] > 0 ? ordered_json(p.opd_waves[cell]) : ordered_json());
        }
        rows.push_back(std::move(row));
    }
    return rows;
}

ordered_json figure_json(const WavefrontFigure& f) {
    ordered_json j;
    j["field"] = f.field;
    j["wavelength_nm"] = f.wavelength_nm;
    if (!f.wavefront) {
        j["error"] = f.error;
        return j;
    }
    const FieldWavefront& w = *f.wavefront;
    j["rms_waves"] = w.rms_waves;
    j["pv_waves"] = w.pv_waves;
    j["max_step_waves"] = w.max_step_waves;
    j["rms_tilt_removed_waves"] = f.rms_tilt_removed_waves;
    j["strehl"] = f.strehl;
    j["rays_passed"] = w.passed;
    j["rays_lost"] = w.lost;
    j["reference_point"] = {w.reference.x, w.reference.y, w.reference.z};
    j["reference_radius"] = w.reference_radius;
    j["zernike_noll"] = f.noll.coefficients;
    j["zernike_fringe"] = f.fringe.coefficients;
    j["zernike_residual_rms_waves"] = f.noll.residual_rms;
    j["opd_map"] = opd_map_json(w.pupil);
    return j;
}

// Noll coefficient j, or 0 when fewer terms were fitted.
double noll_term(const WavefrontFigure& f, size_t j) {
    return j <= f.noll.coefficients.size() ? f.noll.coefficients[j - 1] : 0.0;
}

}  // namespace

ordered_json wavefront_json(const WavefrontFigures& figures) {
    ordered_json j;
    j["reference"] = figures.centroid_reference ? "centroid" : "chief ray";
    j["image_z"] = figures.image_z;
    j["samples"] = figures.samples;
    j["zernike_terms"] = figures.zernike_terms;
    ordered_json coordinates = ordered_json::array();
    for (int k = 0; k < figures.samples; ++k)
        coordinates.push_back((k - figures.samples / 2 + 0.5) / (0.5 * figures.samples));
    j["pupil_coordinates"] = coordinates;
    ordered_json fields = ordered_json::array();
    for (const WavefrontFigure& f : figures.figures) fields.push_back(figure_json(f));
    j["fields"] = fields;
    return j;
}

std::string wavefront_table(const WavefrontFigures& figures) {
    std::string out = printf_text(
        "\nWavefront against the reference sphere on the %s, image plane at z = %.6g (waves; "
        "Zernike: Noll)\n",
        figures.centroid_reference ? "PSF's centroid" : "chief ray's image point", figures.image_z);
    out +=
        "   field  wavelength      RMS       PV   Strehl   Z4 defocus  Z5 astig  Z6 astig   Z7 "
        "coma   Z8 coma  Z11 spherical\n";
    for (const WavefrontFigure& f : figures.figures) {
        if (!f.wavefront) {
            out += printf_text("%8.4g  %10.2f  not measured: %s\n", f.field, f.wavelength_nm,
                               f.error.c_str());
            continue;
        }
        out += printf_text(
            "%8.4g  %10.2f  %7.4f  %7.4f  %7.4f  %11.4f  %8.4f  %8.4f  %8.4f  %8.4f  %13.4f\n",
            f.field, f.wavelength_nm, f.wavefront->rms_waves, f.wavefront->pv_waves, f.strehl,
            noll_term(f, 4), noll_term(f, 5), noll_term(f, 6), noll_term(f, 7), noll_term(f, 8),
            noll_term(f, 11));
    }
    return out;
}

}  // namespace lenslab
