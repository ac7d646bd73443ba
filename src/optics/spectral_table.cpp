#include "optics/spectral_table.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "optics/air_index.h"
#include "optics/smooth_spectrum.h"
#include "optics/spectrum.h"
#include "util/format_number.h"
#include "util/number_list.h"

namespace lenslab {

std::vector<SpectralRow> spectral_rows(const std::vector<double>& nm, double blackbody_k,
                                       const std::optional<Rgb>& light_rgb) {
    for (double l : nm) {
        if (const auto problem = wavelength_problem(l))
            throw std::invalid_argument("wavelength " + format_number(l) + " nm: " + *problem);
    }
    if (blackbody_k != 0) {
        if (const auto problem = blackbody_problem(blackbody_k))
            throw std::invalid_argument("blackbody " + format_number(blackbody_k) +
                                        " K: " + *problem);
    }
    if (light_rgb && (!(std::min({light_rgb->r, light_rgb->g, light_rgb->b}) >= 0) ||
                      light_rgb->is_black() || !light_rgb->is_finite())) {
        throw std::invalid_argument(
            "rgb " + format_number(light_rgb->r) + "," + format_number(light_rgb->g) + "," +
            format_number(light_rgb->b) + ": a light's colour needs channels >= 0, not all 0");
    }
    const SpectrumPtr white = d65_spectrum();
    const SpectrumPtr coloured = light_rgb ? smooth_illuminant_from_rgb(*light_rgb) : nullptr;
    const SpectrumPtr lamp = illuminant_a_spectrum();
    const SpectrumPtr hot = blackbody_k != 0 ? blackbody_spectrum(blackbody_k) : nullptr;
    std::vector<SpectralRow> rows;
    for (double l : nm) {
        SpectralRow r;
        r.nm = l;
        r.cmf = cie_xyz_bar(l);
        r.d65 = white->eval(l) / white->eval(560);
        r.illuminant_a = lamp->eval(l) / lamp->eval(560);
        if (hot) r.blackbody = hot->eval(l) / hot->eval(560);
        if (coloured) r.rgb_light = coloured->eval(l) / white->eval(560);
        r.air_index = standard_air_index(l);
        rows.push_back(r);
    }
    return rows;
}

nlohmann::ordered_json spectral_columns(const std::vector<SpectralRow>& rows, bool blackbody,
                                        bool rgb_light) {
    nlohmann::ordered_json out;
    const auto column = [&rows, &out](const char* key, auto value) {
        out[key] = nlohmann::ordered_json::array();
        for (const SpectralRow& r : rows) out[key].push_back(value(r));
    };
    column("nm", [](const SpectralRow& r) { return r.nm; });
    column("x_bar", [](const SpectralRow& r) { return r.cmf.x; });
    column("y_bar", [](const SpectralRow& r) { return r.cmf.y; });
    column("z_bar", [](const SpectralRow& r) { return r.cmf.z; });
    column("d65", [](const SpectralRow& r) { return r.d65; });
    column("illuminant_a", [](const SpectralRow& r) { return r.illuminant_a; });
    if (blackbody) column("blackbody", [](const SpectralRow& r) { return r.blackbody; });
    if (rgb_light) column("rgb_light", [](const SpectralRow& r) { return r.rgb_light; });
    column("air_index", [](const SpectralRow& r) { return r.air_index; });
    return out;
}

std::vector<double> parse_wavelength_list(const std::string& text) {
    const char separator = text.find(':') != std::string::npos ? ':' : ',';
    std::vector<double> parts;
    try {
        parts = parse_number_list(text, separator);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string(e.what()) + " (give A,B,C or START:END:STEP)");
    }
    if (parts.empty()) {
        throw std::invalid_argument("'" + text +
                                    "': no wavelength given (give A,B,C or START:END:STEP)");
    }
    if (separator == ',') return parts;
    if (parts.size() != 3) {
        throw std::invalid_argument("'" + text + "': a range is START:END:STEP");
    }
    const double start = parts[0], end = parts[1], step = parts[2];
    if (!(step > 0) || end < start) {
        throw std::invalid_argument("'" + text +
                                    "': a range needs END >= START and a STEP above 0");
    }
    const double count = std::floor((end - start) / step + 1e-9) + 1;
    if (count > 10000) {
        throw std::invalid_argument("'" + text + "': more than 10000 wavelengths");
    }
    std::vector<double> out;
    for (int i = 0; i < static_cast<int>(count); ++i) out.push_back(start + i * step);
    return out;
}

}  // namespace lenslab
