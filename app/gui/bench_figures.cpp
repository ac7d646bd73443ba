#include "bench_figures.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "analysis/report/lens_report.h"
#include "optics/glass.h"
#include "util/error.h"
#include "util/format_number.h"
#include "util/number_list.h"

namespace lenslab::gui {

BenchFigures compute_bench_figures(const OpticalSystem& system, const BenchSettings& settings) {
    LensReportOptions options;
    options.wavelengths = settings.wavelengths.empty() ? std::vector<double>{kLineF, kLineD, kLineC}
                                                       : settings.wavelengths;
    options.wavelength_nm = options.wavelengths[(options.wavelengths.size() - 1) / 2];
    options.spot_rings = settings.rings;
    options.first_order.stop = settings.stop - 1;
    options.first_order.epd = settings.epd;
    options.first_order.ray_aiming = settings.ray_aiming;
    options.first_order.fields =
        settings.fields.empty() ? std::vector<double>{0.0} : settings.fields;
    const LensReport report = analyze_lens_system(system, options);
    const std::vector<double>& fields = options.first_order.fields;
    BenchFigures out;
    // Each figure on its own: one that fails (a field no ray passes) leaves the others.
    const auto attempt = [&out](const char* name, const auto& work) {
        try {
            work();
        } catch (const lenslab::Error& e) {
            out.errors.push_back(std::string(name) + ": " + e.what());
        } catch (const std::invalid_argument& e) {  // the diffraction figures' "no ray passes"
            out.errors.push_back(std::string(name) + ": " + e.what());
        }
    };
    attempt("spots", [&] {
        SpotOptions spot;
        spot.fields = fields;
        spot.wavelengths = report.wavelengths;
        spot.rings = settings.rings;
        out.spots = spot_diagrams(system, report.first_order, spot);
    });
    attempt("fans", [&] {
        RayFanOptions fan;
        fan.fields = fields;
        fan.wavelengths = report.wavelengths;
        fan.points = settings.fan_points;
        out.fans = ray_fans(system, report.first_order, fan);
    });
    attempt("field curves", [&] {
        FieldCurveOptions curve;
        for (double field : fields) curve.max_field = std::max(curve.max_field, std::abs(field));
        curve.points = settings.field_curve_points;
        curve.wavelengths = report.wavelengths;
        out.curves = field_curves(system, report.first_order, curve);
    });
    attempt("MTF", [&] {
        RayPupilOptions pupil;
        pupil.wavelength_nm = options.wavelength_nm;
        pupil.aperture_radius = 0.5 * report.first_order.entrance_pupil.diameter;
        pupil.sampling.samples = settings.pupil_samples;
        out.diffraction = diffraction_figures(system, pupil, {});
        FieldMtfOptions mtf;
        mtf.fields = fields;
        mtf.wavelengths = report.wavelengths;
        mtf.frequencies = out.diffraction->mtf.frequencies;
        mtf.samples = settings.pupil_samples;
        mtf.image_z = out.diffraction->image_z;
        out.mtf = field_mtfs(system, report.first_order, mtf);
    });
    if (!out.diffraction) return out;
    const double image_z = out.diffraction->image_z;
    if (settings.psf) {
        attempt("PSF", [&] {
            FieldPsfOptions psf;
            psf.fields = fields;
            psf.wavelengths = report.wavelengths;
            psf.image_z = image_z;
            out.psfs = field_psfs(system, report.first_order, psf);
        });
    }
    if (settings.wavefront) {
        attempt("wavefront", [&] {
            WavefrontFigureOptions wavefront;
            wavefront.fields = fields;
            wavefront.wavelengths = {options.wavelength_nm};
            wavefront.image_z = image_z;
            out.wavefronts = wavefront_figures(system, report.first_order, wavefront);
        });
    }
    return out;
}

std::optional<std::vector<double>> number_list(const std::string& text) {
    try {
        return parse_number_list(text);
    } catch (const std::invalid_argument&) {
        return std::nullopt;
    }
}

std::string number_list_text(const std::vector<double>& values) {
    std::string text;
    for (double v : values) text += (text.empty() ? "" : ", ") + printf_text("%.10g", v);
    return text;
}

}  // namespace lenslab::gui
