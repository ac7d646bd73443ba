#include "analysis/report/analyze_request.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analysis/diffraction/opd_fans.h"
#include "analysis/figures/analyze_figures.h"
#include "analysis/figures/diffraction_maps.h"
#include "analysis/report/curve_report.h"
#include "analysis/report/diffraction_report.h"
#include "analysis/report/fan_report.h"
#include "analysis/report/field_map_report.h"
#include "analysis/report/spot_report.h"
#include "analysis/report/wavefront_report.h"
#include "analysis/system/lens_bench_defaults.h"
#include "analysis/system/lens_lookup.h"
#include "image/image_io.h"
#include "scene/json_reader.h"
#include "util/scene_error.h"

namespace lenslab {

namespace {

// The middle of the wavelengths as given (for an even count, the one before the middle).
double middle_wavelength(const std::vector<double>& wavelengths) {
    return wavelengths[(wavelengths.size() - 1) / 2];
}

// A figure file of a request and its key in the JSON document.
struct FigureFile {
    const std::string& file;
    const char* key;
};

// The stop's surface index (0-based): --stop, else the lens file's stop, the surface at its
// place or a stop in air put there, else the first surface.
int resolve_stop(OpticalSystem& system, const AnalyzeRequest& a) {
    const int surfaces = static_cast<int>(system.surfaces.size());
    if (a.stop != 0) {
        if (a.stop < 1 || a.stop > surfaces) {
            throw AnalyzeRequestError("--stop " + std::to_string(a.stop) + ": the system has " +
                                      std::to_string(surfaces) + " surfaces, numbered 1 to " +
                                      std::to_string(surfaces));
        }
        return a.stop - 1;
    }
    if (!a.stop_position) return 0;
    if (const std::optional<int> at = surface_at(system, *a.stop_position)) return *at;
    // A stop in air needs its rim unless the pupil is set otherwise.
    const double rim = a.stop_semi_diameter > 0 ? a.stop_semi_diameter : system.max_semi_diameter();
    return insert_air_stop(system, *a.stop_position, rim);
}

AnalyzeResults measure(const Scene& scene, const AnalyzeRequest& a, std::optional<int> lens) {
    AnalyzeResults out;
    out.system = build_optical_system(scene, lens);
    const int stop = resolve_stop(out.system, a);
    const OpticalSystem& system = out.system;
    for (double angle : a.fields) {
        if (!(std::abs(angle) < 90.0)) {
            throw AnalyzeRequestError("--fields: " + format_number(angle) +
                                      " degrees is not a field angle (between -90 and 90)");
        }
    }
    LensReportOptions options;
    options.wavelength_nm =
        a.wavelengths.empty() ? a.wavelength_nm : middle_wavelength(a.wavelengths);
    options.wavelengths = a.wavelengths;
    FirstOrderOptions& first = options.first_order;
    first.stop = stop;
    first.ray_aiming = a.ray_aiming.value_or(RayAiming::Real);
    first.epd = a.epd;
    first.f_number = a.f_number;
    if (a.object_distance > 0) {
        first.object_distance = a.object_distance;
        if (!a.field_heights.empty()) first.fields = a.field_heights;
    } else if (!a.fields.empty()) {
        first.fields = a.fields;
    }
    if (a.aperture > 0) {
        check_wavelength(system, options.wavelength_nm, "--wavelength");
        const double usable = usable_aperture_radius(system, options.wavelength_nm);
        if (0.5 * a.aperture > usable * (1.0 + 1e-9)) {
            char usable_text[32];
            std::snprintf(usable_text, sizeof usable_text, "%.6g", 2.0 * usable);
            throw AnalyzeRequestError(
                "--aperture: a beam of diameter " + format_number(a.aperture) +
                " does not pass the lenses (the largest that does is " + usable_text + ")");
        }
        options.aperture_radius = 0.5 * a.aperture;
    }
    options.parts = report_parts(a.report_keys);
    out.report = analyze_lens_system(system, options);
    const LensReport& report = out.report;
    if (a.spots) {
        SpotOptions spot;
        spot.fields = first.fields;
        spot.wavelengths = report.wavelengths;
        spot.weights = a.wavelength_weights;
        spot.rings = a.rings;
        if (a.image_distance) spot.image_z = system.last_vertex() + *a.image_distance;
        out.spots = spot_diagrams(system, report.first_order, spot);
    }
    // The ray fans and the OPD fans sample the same lines of the stop.
    RayFanOptions fan;
    fan.fields = first.fields;
    fan.wavelengths = report.wavelengths;
    fan.points = a.fan_points;
    if (a.image_distance) fan.image_z = system.last_vertex() + *a.image_distance;
    if (a.fans) out.fans = ray_fans(system, report.first_order, fan);
    if (a.opd_fans) out.opd_fans = opd_fans(system, report.first_order, fan);
    if (a.psf || a.mtf || a.through_focus > 0) {
        RayPupilOptions pupil;
        pupil.wavelength_nm = options.wavelength_nm;
        pupil.aperture_radius = 0.5 * report.first_order.entrance_pupil.diameter;
        out.diffraction = diffraction_figures(system, pupil, a.mtf_frequencies);
    }
    const double diffraction_z = a.image_distance
                                     ? system.last_vertex() + *a.image_distance
                                     : (out.diffraction ? out.diffraction->image_z : 0);
    if (a.psf) {
        FieldPsfOptions psf;
        psf.fields = first.fields;
        psf.wavelengths = report.wavelengths;
        psf.weights = a.wavelength_weights;
        psf.image_z = diffraction_z;
        psf.method = a.psf_huygens ? PsfMethod::Huygens : PsfMethod::Transform;
        out.field_psf = field_psfs(system, report.first_order, psf);
    }
    // The MTF's fields, wavelengths and plane, for --mtf and --through-focus alike.
    FieldMtfOptions mtf;
    mtf.fields = first.fields;
    mtf.wavelengths = report.wavelengths;
    mtf.weights = a.wavelength_weights;
    mtf.image_z = diffraction_z;
    if (a.mtf) {
        mtf.frequencies = out.diffraction->mtf.frequencies;
        out.field_mtf = field_mtfs(system, report.first_order, mtf);
    }
    if (a.through_focus > 0) {
        const FirstOrder& f = report.first_order;
        const double lambda = f.wavelength_nm * 1e-6;
        const double range = a.through_focus_range > 0
                                 ? a.through_focus_range
                                 : 8 * lambda * f.working_f_number * f.working_f_number;
        std::vector<double> shifts;
        for (int k = 0; k < a.through_focus_points; ++k)
            shifts.push_back(-range + 2 * range * k / (a.through_focus_points - 1));
        out.through_focus =
            through_focus_mtf(system, report.first_order, mtf, a.through_focus, shifts);
    }
    if (a.wavefront) {
        WavefrontFigureOptions wavefront;
        wavefront.fields = first.fields;
        wavefront.wavelengths = report.wavelengths;
        wavefront.samples = a.wavefront_samples;
        wavefront.zernike_terms = a.zernike_terms;
        wavefront.centroid_reference = a.wavefront_reference == "centroid";
        if (a.image_distance) wavefront.image_z = system.last_vertex() + *a.image_distance;
        try {
            out.wavefronts = wavefront_figures(system, report.first_order, wavefront);
        } catch (const std::invalid_argument& e) {
            throw AnalyzeRequestError(std::string("--wavefront: ") + e.what());
        }
    }
    if (a.field_curves) {
        FieldCurveOptions curve;
        for (double field : first.fields) {
            curve.max_field = std::max(curve.max_field, std::abs(field));
        }
        curve.points = a.field_curve_points;
        curve.wavelengths = report.wavelengths;
        if (a.image_distance) curve.image_z = system.last_vertex() + *a.image_distance;
        out.curves = field_curves(system, report.first_order, curve);
    }
    if (a.field_map > 0) {
        FieldMapOptions map;
        for (double field : first.fields) map.max_field = std::max(map.max_field, std::abs(field));
        if (!(map.max_field > 0)) {
            throw AnalyzeRequestError(
                "--field-map: the fields reach no further than the axis; give --fields (or "
                "--field-heights) out to the edge of the field to map");
        }
        map.points = a.field_map;
        map.wavelength_nm = report.first_order.wavelength_nm;
        map.rings = a.rings;
        map.image_z = system.last_vertex() +
                      (a.image_distance ? *a.image_distance : report.first_order.image_position);
        out.field_map = field_map(system, report.first_order, map);
    }
    if (a.focal_shift) {
        FirstOrderOptions reference = first;
        reference.wavelength_nm = options.wavelength_nm;
        const double from = a.band.empty() ? report.short_nm : a.band[0];
        const double to = a.band.empty() ? report.long_nm : a.band[1];
        out.shift = chromatic_focal_shift(system, reference, from, to, a.focal_shift_points);
    }
    const std::pair<const std::string*, const char*> files[] = {{&a.svg, "ray_diagram"},
                                                                {&a.spots_svg, "spots"},
                                                                {&a.fans_svg, "fans"},
                                                                {&a.curves_svg, "field_curves"},
                                                                {&a.focal_shift_svg, "focal_shift"},
                                                                {&a.mtf_svg, "mtf"},
                                                                {&a.opd_fans_svg, "opd_fans"}};
    for (const auto& [file, name] : files) {
        if (!file->empty()) write_bench_figure(*file, bench_figure(out, a, name));
    }
    const std::string field_unit =
        a.object_distance > 0 ? (a.unit.empty() ? "units" : a.unit) : "deg";
    if (!a.psf_png.empty()) {
        write_png_image(
            psf_map_image(out.field_psf, a.psf_log ? ColourScale::Log : ColourScale::Linear,
                          a.unit.empty() ? "units" : a.unit, field_unit),
            a.psf_png);
    }
    if (!a.opd_png.empty())
        write_png_image(
            opd_map_image(*out.wavefronts, report.first_order.wavelength_nm, field_unit),
            a.opd_png);
    return out;
}

// A lens file's data is for its own lens: not when --lens picks another object.
bool bench_applies(const Scene& scene, const LensBench& bench, const std::string& lens) {
    if (bench.object < 0 || lens.empty()) return true;
    const LensLookup lookup = find_lens(scene, lens);
    return lookup.index && scene.objects[static_cast<size_t>(*lookup.index)].source == bench.object;
}

}  // namespace

AnalyzeRequest with_implied_tables(AnalyzeRequest a) {
    a.spots = a.spots || !a.spots_svg.empty();
    a.fans = a.fans || !a.fans_svg.empty();
    a.opd_fans = a.opd_fans || !a.opd_fans_svg.empty();
    a.field_curves = a.field_curves || !a.curves_svg.empty();
    a.focal_shift = a.focal_shift || !a.focal_shift_svg.empty();
    a.mtf = a.mtf || !a.mtf_svg.empty();
    a.psf = a.psf || !a.psf_png.empty();
    a.wavefront = a.wavefront || !a.opd_png.empty();
    return a;
}

std::optional<std::string> figure_option_error(const AnalyzeRequest& a) {
    const std::vector<double>& weights = a.wavelength_weights;
    if (a.image_distance && !a.spots && !a.fans && !a.opd_fans && !a.field_curves &&
        a.field_map == 0 && !a.wavefront && !a.mtf) {
        return "--image-distance: it places the image plane of --spots, --fans, --opd-fans, "
               "--field-map, --field-curves, --wavefront and --mtf, none of which was asked for";
    }
    if (a.wavefront_samples % 2 != 0) {
        return "--wavefront-samples: " + std::to_string(a.wavefront_samples) +
               " is odd (an even number puts the pupil's centre between samples, as the FFT "
               "grid needs)";
    }
    if (a.psf_huygens && !a.psf)
        return "--psf-huygens: it sets how --psf (or --psf-png) finds each field's PSF, which was "
               "not asked for";
    if (a.psf_log && a.psf_png.empty())
        return "--psf-log: it sets the scale of --psf-png, which was not asked for";
    for (const std::string* png : {&a.psf_png, &a.opd_png}) {
        const std::string suffix = ".png";
        if (!png->empty() &&
            (png->size() <= suffix.size() ||
             png->compare(png->size() - suffix.size(), suffix.size(), suffix) != 0))
            return std::string(png == &a.psf_png ? "--psf-png" : "--opd-png") + ": '" + *png +
                   "' does not end in .png (the figure is a PNG picture)";
    }
    if (!a.mtf_frequencies.empty() && !a.mtf) {
        return "--mtf-frequencies requires --mtf (or --mtf-svg)";
    }
    if (!a.band.empty() && !a.focal_shift) {
        return "--band: it sets the band of --focal-shift, which was not asked for";
    }
    if (!a.band.empty() && (a.band.size() != 2 || !(a.band[0] < a.band[1]))) {
        return "--band: two wavelengths in nm, the shorter first (e.g. 450,700)";
    }
    if (!weights.empty()) {
        const size_t count = std::max<size_t>(1, a.wavelengths.size());
        if (weights.size() != count) {
            return "--wavelength-weights: " + std::to_string(weights.size()) + " weights for " +
                   std::to_string(count) + " wavelengths (one each, in the order of --wavelengths)";
        }
        double sum = 0;
        for (double w : weights) {
            if (w < 0) {
                return "--wavelength-weights: " + format_number(w) +
                       " is negative (a weight is 0 or more)";
            }
            sum += w;
        }
        if (!(sum > 0)) return "--wavelength-weights: they add up to zero";
    }
    return std::nullopt;
}

AnalyzeResults analyze_scene(const Scene& scene, const AnalyzeRequest& request,
                             const std::string& scene_file) {
    LensBenchDefaults defaults{request, {}, {}};
    if (scene.bench && bench_applies(scene, *scene.bench, request.lens))
        defaults = with_lens_bench_defaults(request, *scene.bench);
    const AnalyzeRequest a = with_implied_tables(defaults.request);
    if (const auto error = figure_option_error(a)) throw AnalyzeRequestError(*error);
    std::optional<int> lens;
    if (!a.lens.empty()) {
        const LensLookup lookup = find_lens(scene, a.lens);
        if (!lookup.index) {
            throw AnalyzeRequestError(
                "--lens: " +
                no_lens_message(a.lens, scene_file.empty() ? "the scene" : scene_file, lookup));
        }
        lens = lookup.index;
    }
    try {
        AnalyzeResults results = measure(scene, a, lens);
        results.from_lens_file = defaults.taken;
        results.not_from_lens_file = defaults.not_taken;
        return results;
    } catch (const SceneError& e) {
        // The scene loaded but is not a lens system the bench can measure: name the file too.
        if (scene_file.empty()) throw;
        throw SceneError(scene_file + ": " + e.path(), e.reason());
    }
}

namespace {

// The document's keys past the lens report's, in order, each as `put(key, value)` with a
// callable for its value: one list for analyze_json and analyze_json_keys.
template <class Put>
void for_each_bench_key(const AnalyzeResults& results, const AnalyzeRequest& request,
                        const std::string& scene_file, Put&& put) {
    using BenchJson = nlohmann::ordered_json;
    const AnalyzeRequest a = with_implied_tables(request);
    if (!scene_file.empty()) put("scene", [&] { return BenchJson(scene_file); });
    if (!results.from_lens_file.empty() || !results.not_from_lens_file.empty()) {
        put("lens_file_bench", [&] {
            return BenchJson{{"taken", results.from_lens_file},
                             {"not_taken", results.not_from_lens_file}};
        });
    }
    if (!a.svg.empty()) put("svg", [&] { return BenchJson(a.svg); });
    const FigureFile figures[] = {
        {a.spots_svg, "spots_svg"},   {a.fans_svg, "fans_svg"},
        {a.curves_svg, "curves_svg"}, {a.focal_shift_svg, "focal_shift_svg"},
        {a.mtf_svg, "mtf_svg"},       {a.opd_fans_svg, "opd_fans_svg"},
        {a.psf_png, "psf_png"},       {a.opd_png, "opd_png"}};
    for (const FigureFile& figure : figures) {
        if (!figure.file.empty()) put(figure.key, [&] { return BenchJson(figure.file); });
    }
    if (a.psf) put("psf", [&] { return psf_json(*results.diffraction, results.field_psf); });
    if (a.mtf) put("mtf", [&] { return mtf_json(*results.diffraction, *results.field_mtf); });
    if (results.through_focus)
        put("through_focus", [&] { return through_focus_json(*results.through_focus); });
    if (results.wavefronts) put("wavefront", [&] { return wavefront_json(*results.wavefronts); });
    if (results.spots) put("spots", [&] { return spots_json(results.system, *results.spots); });
    if (results.fans) put("fans", [&] { return fans_json(results.system, *results.fans); });
    if (results.opd_fans) {
        put("opd_fans",
            [&] { return fans_json(results.system, *results.opd_fans, FanQuantity::Opd); });
    }
    if (results.curves) {
        put("field_curves", [&] { return field_curves_json(results.system, *results.curves); });
    }
    if (results.shift) put("focal_shift", [&] { return focal_shift_json(*results.shift); });
    if (results.field_map) {
        put("field_map", [&] { return field_map_json(results.system, *results.field_map); });
    }
}

}  // namespace

nlohmann::ordered_json analyze_json(const AnalyzeResults& results, const AnalyzeRequest& request,
                                    const std::string& scene_file) {
    const std::vector<std::string>& keys = request.report_keys;
    nlohmann::ordered_json j = report_json(results.system, results.report, keys);
    for_each_bench_key(results, request, scene_file, [&](const char* key, auto value) {
        if (keys.empty() || std::find(keys.begin(), keys.end(), key) != keys.end())
            j[key] = value();
    });
    return j;
}

std::vector<std::string> analyze_json_keys(const AnalyzeResults& results,
                                           const AnalyzeRequest& request,
                                           const std::string& scene_file) {
    std::vector<std::string> keys = report_json_keys();
    for_each_bench_key(results, request, scene_file,
                       [&](const char* key, auto) { keys.emplace_back(key); });
    return keys;
}

nlohmann::ordered_json analyze_report(const Scene& scene, const AnalyzeRequest& request,
                                      const std::string& scene_file) {
    return analyze_json(analyze_scene(scene, request, scene_file), request, scene_file);
}

}  // namespace lenslab
