#include "analysis/report/diffraction_report.h"

#include <cstdio>

namespace lenslab {

namespace {

// Only the axial field is measured so far (diffraction_figures.h traces an axial beam).
constexpr double kAxialField = 0.0;

template <class... Numbers>
std::string diffraction_line(const char* format, Numbers... numbers) {
    char text[160];
    std::snprintf(text, sizeof text, format, numbers...);
    return text;
}

}  // namespace

nlohmann::ordered_json psf_json(const DiffractionFigures& figures) {
    nlohmann::ordered_json j;
    j["strehl"] = figures.strehl;
    j["wavefront_rms_waves"] = figures.wavefront_rms;
    j["airy_radius"] = figures.airy_radius;
    j["encircled_energy_at_airy_radius"] = figures.encircled_energy_at_airy_radius;
    j["sample_spacing"] = figures.psf.spacing;
    j["image_z"] = figures.image_z;
    j["wavelength_nm"] = figures.wavelength_nm;
    j["f_number"] = figures.f_number;
    return j;
}

nlohmann::ordered_json mtf_json(const DiffractionFigures& figures) {
    nlohmann::ordered_json j;
    j["frequencies"] = figures.mtf.frequencies;
    j["cutoff"] = figures.psf.cutoff;
    j["diffraction_limit"] = figures.mtf.diffraction_limit;
    nlohmann::ordered_json field;
    field["field"] = kAxialField;
    field["tangential"] = figures.mtf.tangential;
    field["sagittal"] = figures.mtf.sagittal;
    j["fields"] = nlohmann::ordered_json::array({field});
    j["wavelength_nm"] = figures.wavelength_nm;
    return j;
}

std::string diffraction_table(const DiffractionFigures& figures, bool psf, bool mtf) {
    std::string out = diffraction_line(
        "\nDiffraction on the axis at %.2f nm, F/%.4g, best focus (%.4f behind the first vertex)\n",
        figures.wavelength_nm, figures.f_number, figures.image_z);
    if (psf) {
        out += diffraction_line("  Strehl ratio %.4f   wavefront RMS %.4f waves\n", figures.strehl,
                                figures.wavefront_rms);
        out +=
            diffraction_line("  Airy radius 1.22 lambda N = %.6f   encircled energy there %.4f\n",
                             figures.airy_radius, figures.encircled_energy_at_airy_radius);
    }
    if (mtf) {
        out += "  MTF (cycles/mm)                tangential  sagittal  diffraction limit\n";
        for (size_t i = 0; i < figures.mtf.frequencies.size(); ++i) {
            out += diffraction_line("  %10.2f                       %.4f      %.4f    %.4f\n",
                                    figures.mtf.frequencies[i], figures.mtf.tangential[i],
                                    figures.mtf.sagittal[i], figures.mtf.diffraction_limit[i]);
        }
    }
    return out;
}

}  // namespace lenslab
