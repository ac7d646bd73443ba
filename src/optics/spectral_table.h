#pragma once
// The spectral data the renderer uses, at chosen wavelengths, for checking it against the
// published tables: `lenslab spectra` prints it and Python's lenslab.spectral_data returns it.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "math/vec3.h"
#include "optics/rgb.h"

namespace lenslab {

struct SpectralRow {
    double nm = 0;
    Vec3 cmf;                 // CIE 1931 2-degree colour-matching functions x, y, z bar
    double d65 = 0;           // the renderer's white light (D65), relative to its value at 560 nm
    double illuminant_a = 0;  // CIE illuminant A, relative to 560 nm
    double blackbody = 0;     // the asked blackbody's spectrum, relative to 560 nm; 0 if none
    // The spectrum a light of the asked RGB colour gets (optics/smooth_spectrum.h), relative
    // to D65's value at 560 nm (so colour 1,1,1 gives the d65 column); 0 if none asked.
    double rgb_light = 0;
    double air_index = 0;  // standard air's index (20 degC, 101 325 Pa) at this air wavelength
};

// One row per wavelength (each from kLambdaMinNm to kLambdaMaxNm, the tables' range); with
// `blackbody_k` 0, no blackbody, else from kBlackbodyMinK to kBlackbodyMaxK; `light_rgb`, a
// light colour (channels >= 0, not all 0). Throws std::invalid_argument naming the value out
// of range.
std::vector<SpectralRow> spectral_rows(const std::vector<double>& nm, double blackbody_k = 0,
                                       const std::optional<Rgb>& light_rgb = std::nullopt);

// The rows as columns, one array per quantity: {"nm": [...], "x_bar": [...], "y_bar",
// "z_bar", "d65", "illuminant_a", "blackbody" (when asked for), "rgb_light" (when asked
// for), "air_index"}.
nlohmann::ordered_json spectral_columns(const std::vector<SpectralRow>& rows, bool blackbody,
                                        bool rgb_light = false);

// "START:END:STEP" (END included when the steps land on it) or "A,B,C": the wavelengths
// asked for. Throws std::invalid_argument saying what is wrong.
std::vector<double> parse_wavelength_list(const std::string& text);

}  // namespace lenslab
