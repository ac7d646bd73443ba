#include "scene/spectral_json.h"

#include "optics/glass_catalogue_file.h"
#include "optics/glass_library.h"
#include "optics/smooth_spectrum.h"
#include "scene/material.h"

namespace lenslab {

namespace {

std::vector<double> read_numbers(const nlohmann::json& j, const std::string& path) {
    if (!j.is_array() || j.empty() || j.size() > 8) {
        throw SceneError(path, "must be an array of 1 to 8 numbers");
    }
    std::vector<double> out;
    for (size_t i = 0; i < j.size(); ++i) {
        out.push_back(JsonObjectReader::as_number(j[i], path + "[" + std::to_string(i) + "]"));
    }
    return out;
}

}  // namespace

IndexModelPtr read_index_model(const nlohmann::json& j, const std::string& path) {
    if (j.is_number()) {
        const double n = JsonObjectReader::as_number(j, path);
        if (!(n > 0)) throw SceneError(path, "must be > 0, got " + format_number(n));
        return constant_index(n);
    }
    if (!j.is_object()) {
        throw SceneError(path, "must be a number or a model {\"model\": \"sellmeier\", ...}");
    }
    const std::string model = JsonObjectReader(j, path, {"model", "A", "B", "C", "n_d", "V_d"})
                                  .choice("model", "sellmeier", {"cauchy", "sellmeier", "abbe"});
    IndexModelPtr m;
    if (model == "cauchy") {
        JsonObjectReader r(j, path, {"model", "A", "B", "C"}, "a Cauchy model");
        m = cauchy_index(r.positive("A"), r.number("B"), r.number("C", 0.0));
    } else if (model == "sellmeier") {
        JsonObjectReader r(j, path, {"model", "B", "C"}, "a Sellmeier model");
        const auto b = read_numbers(r.require("B"), r.child_path("B"));
        const auto c = read_numbers(r.require("C"), r.child_path("C"));
        if (b.size() != c.size()) {
            throw SceneError(r.child_path("C"),
                             "must have as many terms as B (" + std::to_string(b.size()) + ")");
        }
        // n² = 1 + Σ B·λ²/(λ² − C) is infinite at λ² = C: a pole inside the visible range
        // (which sampling every 10 nm can step over) makes every figure NaN.
        const double lo = kLambdaMinNm * 1e-3, hi = kLambdaMaxNm * 1e-3;  // µm
        for (size_t i = 0; i < c.size(); ++i) {
            if (b[i] != 0.0 && c[i] >= lo * lo && c[i] <= hi * hi) {
                throw SceneError(r.child_path("C") + "[" + std::to_string(i) + "]",
                                 "n² = 1 + Σ B·λ²/(λ² − C) has a pole at λ = √C = " +
                                     format_number(std::sqrt(c[i]) * 1e3) +
                                     " nm, inside 360-830 nm (C is in µm²: each must be below " +
                                     format_number(lo * lo) + " or above " +
                                     format_number(hi * hi) + ")");
            }
        }
        m = sellmeier_index(b, c);
    } else {
        JsonObjectReader r(j, path, {"model", "n_d", "V_d"}, "an Abbe model");
        const double nd = r.positive("n_d");
        if (nd <= 1.0)
            throw SceneError(r.child_path("n_d"), "must be > 1, got " + format_number(nd));
        m = abbe_index(nd, r.positive("V_d"));
    }
    // A model whose index is not a real number > 0 across the visible range is a typo.
    for (double nm = kLambdaMinNm; nm <= kLambdaMaxNm; nm += 10.0) {
        const double n = m->n(nm);
        if (!(n > 0.0) || !std::isfinite(n)) {
            throw SceneError(path, "the model gives n = " + format_number(n) + " at " +
                                       format_number(nm) +
                                       " nm (must be a positive number across 360-830 nm)");
        }
    }
    return m;
}

const Glass& read_glass(const nlohmann::json& j, const std::string& path) {
    if (!j.is_string()) throw SceneError(path, "must be the name of a catalogue glass");
    const std::string name = j.get<std::string>();
    try {
        const GlassLookup found = lookup_glass(name);
        if (found.glass) return *found.glass;
        throw SceneError(path, found.error);
    } catch (const GlassDataError& e) {
        throw SceneError(path, std::string("cannot look up glass '") + name + "': " + e.what());
    }
}

SpectrumPtr read_spectrum(const nlohmann::json& j, const std::string& path) {
    if (j.is_string()) {
        std::string names;
        for (const NamedSpectrum& named : named_spectra()) {
            if (j.get<std::string>() == named.name) return named.make();
            names += "\"" + named.name + "\", ";
        }
        throw SceneError(path, "unknown spectrum '" + j.get<std::string>() + "' (use " + names +
                                   "{\"blackbody\": K} or {\"line\": nm})");
    }
    JsonObjectReader r(j, path, {"blackbody", "line", "width"}, "a spectrum");
    if (r.has("blackbody")) {
        const double k = r.positive("blackbody");
        if (const auto problem = blackbody_problem(k))
            throw SceneError(r.child_path("blackbody"), *problem + ", got " + format_number(k));
        return blackbody_spectrum(k);
    }
    if (r.has("line")) {
        const double nm = r.number("line");
        if (const auto problem = wavelength_problem(nm))
            throw SceneError(r.child_path("line"), format_number(nm) + " nm: " + *problem);
        return line_spectrum(nm, r.positive("width", 1.0));
    }
    throw SceneError(path, "give \"blackbody\" (kelvin) or \"line\" (nm)");
}

SpectrumPtr light_spectrum(JsonObjectReader& r, Rgb& color, double power) {
    if (const nlohmann::json* s = r.find("spectrum")) {
        if (r.has("color"))
            throw SceneError(r.child_path("color"), "give either color or spectrum, not both");
        return scaled_spectrum(read_spectrum(*s, r.child_path("spectrum")), power);
    }
    color = r.color("color", color);
    return scaled_spectrum(smooth_illuminant_from_rgb(color), power);
}

SpectrumPtr laser_spectrum(JsonObjectReader& r, double wavelength_nm, double power) {
    if (const nlohmann::json* s = r.find("spectrum")) {
        if (r.has("wavelength"))
            throw SceneError(r.child_path("wavelength"),
                             "give either wavelength or spectrum, not both");
        return scaled_spectrum(read_spectrum(*s, r.child_path("spectrum")), power);
    }
    return scaled_spectrum(line_spectrum(wavelength_nm, 0.1), power);
}

}  // namespace lenslab
