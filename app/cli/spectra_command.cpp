// `lenslab spectra [--wavelengths LIST] [--blackbody K] [--rgb R,G,B] [--json]`: the spectral
// data the renderer uses (optics/spectral_table.h), printed for checking against published
// tables.

#include <cstdio>
#include <iostream>
#include <memory>
#include <stdexcept>

#include "commands.h"
#include "optics/spectral_table.h"
#include "util/error.h"

namespace lenslab::cli {

namespace {

struct SpectraArgs {
    std::string wavelengths = "380:780:20";
    double blackbody = 0;
    std::vector<double> rgb;  // a light colour, or empty
    bool json = false;
};

int print_spectra(const SpectraArgs& a) {
    std::vector<double> nm;
    try {
        nm = parse_wavelength_list(a.wavelengths);
    } catch (const std::invalid_argument& e) {
        throw Error(std::string("--wavelengths ") + e.what());
    }
    std::vector<SpectralRow> rows;
    try {
        const std::optional<Rgb> light =
            a.rgb.empty() ? std::nullopt : std::optional<Rgb>(Rgb{a.rgb[0], a.rgb[1], a.rgb[2]});
        rows = spectral_rows(nm, a.blackbody, light);
    } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        const bool option = what.rfind("blackbody", 0) == 0 || what.rfind("rgb", 0) == 0;
        throw Error((option ? "--" : "--wavelengths: ") + what);
    }
    const bool coloured = !a.rgb.empty();
    if (a.json) {
        std::cout << spectral_columns(rows, a.blackbody != 0, coloured).dump(2) << "\n";
        return 0;
    }
    std::printf("%8s %9s %9s %9s %9s %12s%s%s %11s\n", "nm", "x_bar", "y_bar", "z_bar", "d65",
                "illuminant_a", a.blackbody != 0 ? "  blackbody" : "",
                coloured ? "  rgb_light" : "", "air_index");
    for (const SpectralRow& r : rows) {
        std::printf("%8.3f %9.6f %9.6f %9.6f %9.6f %12.6f", r.nm, r.cmf.x, r.cmf.y, r.cmf.z, r.d65,
                    r.illuminant_a);
        if (a.blackbody != 0) std::printf(" %10.6f", r.blackbody);
        if (coloured) std::printf(" %10.6f", r.rgb_light);
        std::printf(" %11.8f\n", r.air_index);
    }
    std::printf(
        "(CIE 1931 2-degree colour-matching functions; d65: the renderer's white light, "
        "illuminant_a (CIE A) and blackbody, relative to 560 nm; rgb_light: a light of that "
        "colour, "
        "relative to d65 at 560 nm; air_index: standard air, 20 degC, 101325 Pa, "
        "Birch and Downs 1993, at the wavelength in air)\n");
    return 0;
}

}  // namespace

Action add_spectra_command(CLI::App& app) {
    auto args = std::make_shared<SpectraArgs>();
    CLI::App* cmd = app.add_subcommand(
        "spectra",
        "Print the spectral data the renderer uses: the CIE 1931 colour-matching functions, its "
        "D65 white light, illuminant A, a blackbody and the index of standard air, at chosen "
        "wavelengths");
    cmd->add_option("--wavelengths", args->wavelengths,
                    "Wavelengths in nm: A,B,C or START:END:STEP, within 360 to 830")
        ->capture_default_str();
    cmd->add_option("--blackbody", args->blackbody,
                    "Add a blackbody at this temperature in kelvin (500 to 100000)");
    cmd->add_option("--rgb", args->rgb,
                    "Add the smooth spectrum a light of this linear RGB colour gets (R,G,B)")
        ->delimiter(',')
        ->expected(3);
    cmd->add_flag("--json", args->json, "Print {\"nm\": [...], \"x_bar\": [...], ...} as JSON");
    return [args] { return print_spectra(*args); };
}

}  // namespace lenslab::cli
