// `lenslab analyze SCENE`: the optical bench. Focal lengths, principal planes, spherical and
// chromatic aberration and spot sizes of the lenses on one axis, as a table or JSON, and a
// ray diagram as SVG.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <vector>

#include "analysis/curve_figures.h"
#include "analysis/curve_report.h"
#include "analysis/diffraction_report.h"
#include "analysis/fan_report.h"
#include "analysis/field_figures.h"
#include "analysis/lens_lookup.h"
#include "analysis/lens_report.h"
#include "analysis/ray_diagram.h"
#include "analysis/ray_diagram_image.h"
#include "analysis/ray_diagram_svg.h"
#include "analysis/spot_report.h"
#include "commands.h"
#include "scene/json_reader.h"
#include "scene/scene_json.h"
#include "util/atomic_file.h"

namespace lenslab::cli {

namespace {

struct AnalyzeArgs {
    std::string scene;
    double wavelength_nm = kLineD;
    std::vector<double> wavelengths;  // the primary is the middle one
    bool json = false;
    std::string svg;
    double aperture = 0;  // beam diameter; 0: the usable aperture
    std::string lens;
    std::string unit;  // for the ray diagram's labels; empty: "units"
    int stop = 1;      // 1-based surface index, as lens design programs count
    double epd = 0, f_number = 0;
    double object_distance = 0;  // 0: the object at infinity
    std::vector<double> fields, field_heights;
    bool seidel = false;
    bool psf = false, mtf = false;
    std::vector<double> mtf_frequencies;  // empty: ten up to the cutoff
    bool spots = false;
    int rings = 6;                           // hexapolar rings of the spot diagrams
    std::optional<double> image_distance;    // image plane from the last vertex
    std::vector<double> wavelength_weights;  // one per wavelength; empty: equal
    bool fans = false;
    int fan_points = 21;
    // Figures; each implies its table.
    std::string spots_svg, fans_svg, curves_svg, focal_shift_svg, mtf_svg;
    bool field_curves = false;
    int field_curve_points = 11;
    bool focal_shift = false;
    std::vector<double> band;  // the focal shift's; empty: the wavelengths' range, or F to C
    int focal_shift_points = 21;
};

// A figure as SVG, or as PNG when the file's name ends in ".png"; atomically either way, so a
// failed write leaves no half file and says why it failed.
void write_diagram(const std::string& file, const RayDiagram& diagram, double width,
                   double min_height) {
    const std::string png = ".png";
    if (file.size() > png.size() && file.compare(file.size() - png.size(), png.size(), png) == 0) {
        write_png_image(ray_diagram_image(diagram, width, min_height), file);
    } else {
        write_text_atomically(file, ray_diagram_svg(diagram, width, min_height));
    }
}

// The middle of the wavelengths as given (for an even count, the one before the middle).
double primary_wavelength(const std::vector<double>& wavelengths) {
    return wavelengths[(wavelengths.size() - 1) / 2];
}

int usage_error(const std::string& message) {
    std::cerr << "lenslab: error: " << message << "\n";
    return 2;
}

// What the options of the figures say against each other, before any work: the message of
// the first conflict, if any.
std::optional<std::string> figure_option_error(const AnalyzeArgs& a) {
    const std::vector<double>& weights = a.wavelength_weights;
    if (a.image_distance && !a.spots && !a.fans && !a.field_curves) {
        return "--image-distance: it places the image plane of --spots, --fans "
               "and --field-curves, none of which was asked for";
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

int run(AnalyzeArgs a) {
    // Before the analysis, so a bad path costs nothing.
    for (const std::string* file :
         {&a.svg, &a.spots_svg, &a.fans_svg, &a.curves_svg, &a.focal_shift_svg, &a.mtf_svg}) {
        if (!file->empty()) check_output_file(*file);
    }
    a.spots = a.spots || !a.spots_svg.empty();
    a.fans = a.fans || !a.fans_svg.empty();
    a.field_curves = a.field_curves || !a.curves_svg.empty();
    a.focal_shift = a.focal_shift || !a.focal_shift_svg.empty();
    a.mtf = a.mtf || !a.mtf_svg.empty();
    if (const auto error = figure_option_error(a)) return usage_error(*error);
    const Scene scene = load_scene_file(a.scene, {.require_camera = false});
    std::optional<int> lens;
    if (!a.lens.empty()) {
        const LensLookup lookup = find_lens(scene, a.lens);
        if (!lookup.index)
            return usage_error("--lens: " + no_lens_message(a.lens, a.scene, lookup));
        lens = lookup.index;
    }
    try {
        const OpticalSystem system = build_optical_system(scene, lens);
        const int surfaces = static_cast<int>(system.surfaces.size());
        if (a.stop < 1 || a.stop > surfaces) {
            return usage_error("--stop " + std::to_string(a.stop) + ": the system has " +
                               std::to_string(surfaces) + " surfaces, numbered 1 to " +
                               std::to_string(surfaces));
        }
        for (double angle : a.fields) {
            if (!(std::abs(angle) < 90.0)) {
                return usage_error("--fields: " + format_number(angle) +
                                   " degrees is not a field angle (between -90 and 90)");
            }
        }
        LensReportOptions options;
        options.wavelength_nm =
            a.wavelengths.empty() ? a.wavelength_nm : primary_wavelength(a.wavelengths);
        options.wavelengths = a.wavelengths;
        FirstOrderOptions& first = options.first_order;
        first.stop = a.stop - 1;
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
                return usage_error("--aperture: a beam of diameter " + format_number(a.aperture) +
                                   " does not pass the lenses (the largest that does is " +
                                   usable_text + ")");
            }
            options.aperture_radius = 0.5 * a.aperture;
        }
        const std::vector<double>& weights = a.wavelength_weights;
        const LensReport report = analyze_lens_system(system, options);
        std::optional<SpotDiagrams> spots;
        if (a.spots) {
            SpotOptions spot;
            spot.fields = first.fields;
            spot.wavelengths = report.wavelengths;
            spot.weights = weights;
            spot.rings = a.rings;
            if (a.image_distance) spot.image_z = system.last_vertex() + *a.image_distance;
            spots = spot_diagrams(system, report.first_order, spot);
        }
        std::optional<RayFans> fans;
        if (a.fans) {
            RayFanOptions fan;
            fan.fields = first.fields;
            fan.wavelengths = report.wavelengths;
            fan.points = a.fan_points;
            if (a.image_distance) fan.image_z = system.last_vertex() + *a.image_distance;
            fans = ray_fans(system, report.first_order, fan);
        }
        std::optional<DiffractionFigures> diffraction;
        if (a.psf || a.mtf) {
            RayPupilOptions pupil;
            pupil.wavelength_nm = options.wavelength_nm;
            pupil.aperture_radius = 0.5 * report.first_order.entrance_pupil.diameter;
            diffraction = diffraction_figures(system, pupil, a.mtf_frequencies);
        }
        if (!a.svg.empty()) {
            RayDiagramOptions diagram;
            diagram.unit = a.unit;
            write_diagram(a.svg, make_ray_diagram(system, report, diagram), 1200, 360);
        }
        std::optional<FieldCurves> curves;
        if (a.field_curves) {
            FieldCurveOptions curve;
            for (double field : first.fields) {
                curve.max_field = std::max(curve.max_field, std::abs(field));
            }
            curve.points = a.field_curve_points;
            curve.wavelengths = report.wavelengths;
            if (a.image_distance) curve.image_z = system.last_vertex() + *a.image_distance;
            curves = field_curves(system, report.first_order, curve);
        }
        std::optional<FocalShift> shift;
        if (a.focal_shift) {
            FirstOrderOptions reference = first;
            reference.wavelength_nm = options.wavelength_nm;
            const double from = a.band.empty() ? report.short_nm : a.band[0];
            const double to = a.band.empty() ? report.long_nm : a.band[1];
            shift = chromatic_focal_shift(system, reference, from, to, a.focal_shift_points);
        }
        const std::string field_unit =
            first.object_distance ? (a.unit.empty() ? "units" : a.unit) : "deg";
        const auto write_figure = [](const std::string& file, const RayDiagram& figure,
                                     int panels) {
            write_diagram(file, figure, field_figure_width(panels), 300);
        };
        if (!a.spots_svg.empty()) {
            write_figure(a.spots_svg, spot_diagram_figure(*spots, a.unit, field_unit),
                         static_cast<int>(spots->fields.size()));
        }
        if (!a.fans_svg.empty()) {
            write_figure(a.fans_svg, ray_fan_figure(*fans, a.unit, field_unit), 2);
        }
        if (!a.curves_svg.empty()) {
            write_figure(a.curves_svg, field_curves_figure(*curves, a.unit, field_unit), 2);
        }
        if (!a.focal_shift_svg.empty()) {
            write_figure(a.focal_shift_svg, focal_shift_figure(*shift, a.unit), 1);
        }
        if (!a.mtf_svg.empty()) {
            write_figure(a.mtf_svg, mtf_figure(*diffraction, a.unit), 1);
        }
        // The figures written: file, JSON key, what the table's last lines call them.
        const struct {
            const std::string& file;
            const char* key;
            const char* name;
        } figures[] = {{a.spots_svg, "spots_svg", "spot diagrams"},
                       {a.fans_svg, "fans_svg", "ray fans"},
                       {a.curves_svg, "curves_svg", "field curves"},
                       {a.focal_shift_svg, "focal_shift_svg", "focal shift"},
                       {a.mtf_svg, "mtf_svg", "MTF"}};
        if (a.json) {
            nlohmann::ordered_json j = report_json(system, report);
            j["scene"] = a.scene;
            if (!a.svg.empty()) j["svg"] = a.svg;
            for (const auto& figure : figures) {
                if (!figure.file.empty()) j[figure.key] = figure.file;
            }
            if (a.psf) j["psf"] = psf_json(*diffraction);
            if (a.mtf) j["mtf"] = mtf_json(*diffraction);
            if (spots) j["spots"] = spots_json(system, *spots);
            if (fans) j["fans"] = fans_json(system, *fans);
            if (curves) j["field_curves"] = field_curves_json(system, *curves);
            if (shift) j["focal_shift"] = focal_shift_json(*shift);
            std::cout << j.dump(2) << "\n";
        } else {
            std::cout << "lenslab analyze " << a.scene << ": "
                      << report_table(system, report, a.seidel);
            if (diffraction) std::cout << diffraction_table(*diffraction, a.psf, a.mtf);
            if (spots) std::cout << spots_table(system, *spots);
            if (fans) std::cout << fans_table(system, *fans);
            if (curves) std::cout << field_curves_table(system, *curves);
            if (shift) std::cout << focal_shift_table(*shift);
            if (!a.svg.empty()) std::cout << "\nray diagram written to " << a.svg << "\n";
            for (const auto& figure : figures) {
                if (!figure.file.empty()) {
                    std::cout << figure.name << " written to " << figure.file << "\n";
                }
            }
        }
        return 0;
    } catch (const SceneError& e) {
        // The scene loaded but is not a lens system the bench can measure: name the file too.
        throw SceneError(a.scene + ": " + e.path(), e.reason());
    }
}

}  // namespace

Action add_analyze_command(CLI::App& app) {
    auto args = std::make_shared<AnalyzeArgs>();
    CLI::App* cmd = app.add_subcommand(
        "analyze",
        "Optical bench: focal lengths, aberrations and a ray diagram of the lenses on one axis");
    cmd->add_option("scene", args->scene, "Scene file (JSON); a camera is not needed")->required();
    CLI::Option* wavelength =
        cmd->add_option("-w,--wavelength", args->wavelength_nm,
                        "Wavelength in air in nm for the figures (default: the d line, 587.56 "
                        "nm; in vacuum for a scene with \"ambient\": \"vacuum\")")
            ->check(CLI::PositiveNumber);
    cmd->add_option("--wavelengths", args->wavelengths,
                    "Wavelengths in nm, comma-separated (e.g. 486.1327,587.5618,656.2725): the "
                    "middle one is the primary, for every single-wavelength figure; the "
                    "shortest and longest give the chromatic block and the Seidel colour sums "
                    "(default: the F and C lines)")
        ->delimiter(',')
        ->check(CLI::PositiveNumber)
        ->excludes(wavelength);
    cmd->add_flag("--json", args->json, "Print the figures as JSON");
    cmd->add_option("--svg", args->svg,
                    "Write a ray diagram to this file: SVG, or PNG for a name ending in .png");
    CLI::Option* aperture =
        cmd->add_option("--aperture", args->aperture,
                        "Diameter of the collimated beam, in the scene's unit (default: all the "
                        "lens passes)")
            ->check(CLI::PositiveNumber);
    cmd->add_option("--stop", args->stop,
                    "The aperture stop: a surface, counted from 1 along the light (default: 1, "
                    "the first surface)")
        ->check(whole_number<int>());
    CLI::Option* epd =
        cmd->add_option("--epd", args->epd,
                        "Entrance pupil diameter (default: the beam of --aperture with the stop "
                        "on the first surface, else the stop surface's rim)")
            ->check(CLI::PositiveNumber)
            ->excludes(aperture);
    cmd->add_option("--f-number", args->f_number,
                    "F-number: sets the entrance pupil diameter to EFL / N")
        ->check(CLI::PositiveNumber)
        ->excludes(aperture)
        ->excludes(epd);
    CLI::Option* distance =
        cmd->add_option("--object-distance", args->object_distance,
                        "Distance from the object to the first vertex (default: the object at "
                        "infinity)")
            ->check(CLI::PositiveNumber);
    cmd->add_option("--fields", args->fields,
                    "Field angles in degrees, comma-separated, for an object at infinity "
                    "(default: 0); the chief ray comes from the largest")
        ->delimiter(',')
        ->excludes(distance);
    cmd->add_option("--field-heights", args->field_heights,
                    "Object heights, comma-separated, for an object at --object-distance")
        ->delimiter(',')
        ->needs(distance);
    cmd->add_flag("--seidel", args->seidel,
                  "Print the Seidel sums surface by surface (JSON always has them)");
    cmd->add_flag(
        "--psf", args->psf,
        "Diffraction on the axis at the primary wavelength: the point spread function's "
        "Strehl ratio, wavefront RMS and encircled energy at the best focus (lengths in mm)");
    cmd->add_flag(
        "--mtf", args->mtf,
        "Diffraction MTF on the axis at the primary wavelength, tangential and sagittal, beside "
        "the diffraction limit (frequencies in cycles/mm)");
    cmd->add_option("--mtf-frequencies", args->mtf_frequencies,
                    "Frequencies of the MTF in cycles/mm, comma-separated (default: ten up to "
                    "the cutoff 1/(lambda N))")
        ->delimiter(',')
        ->check(CLI::PositiveNumber);
    cmd->add_flag(
        "--spots", args->spots,
        "Spot diagrams per field and wavelength: RMS and geometric radii about the centroid, "
        "chief ray, vignetting, and per field the polychromatic RMS beside the Airy radius");
    cmd->add_option("--rings", args->rings,
                    "Hexapolar rings of the spot diagrams' beams, Zemax's \"ray density\": 1 + "
                    "3 N (N + 1) rays (default 6: 127)")
        ->check(CLI::Range(1, 200));
    cmd->add_flag(
        "--fans", args->fans,
        "Transverse ray fans per field and wavelength, tangential (e_y against py) and sagittal "
        "(e_x against px), from the primary wavelength's chief ray");
    cmd->add_option("--spots-svg", args->spots_svg,
                    "Write the spot diagrams to this file, SVG or (.png) PNG; implies --spots");
    cmd->add_option("--fans-svg", args->fans_svg,
                    "Write the ray fans to this file, SVG or (.png) PNG; implies --fans");
    cmd->add_option("--curves-svg", args->curves_svg,
                    "Write the field curves (field curvature and distortion) to this file, SVG or "
                    "(.png) PNG; implies --field-curves");
    cmd->add_option("--focal-shift-svg", args->focal_shift_svg,
                    "Write the chromatic focal shift to this file, SVG or (.png) PNG; implies "
                    "--focal-shift");
    cmd->add_option("--mtf-svg", args->mtf_svg,
                    "Write the MTF on the axis beside the diffraction limit to this file, SVG or "
                    "(.png) PNG; implies --mtf");
    cmd->add_option("--fan-points", args->fan_points,
                    "Points along each ray fan, evenly from -1 to 1 across the stop (default 21)")
        ->check(CLI::Range(2, 10001));
    cmd->add_option("--image-distance", args->image_distance,
                    "The image plane of the spots, fans and field curves, from the last vertex "
                    "(default: the "
                    "paraxial image plane at the primary wavelength)");
    cmd->add_flag("--field-curves", args->field_curves,
                  "Tangential and sagittal field curvature and real distortion against field, "
                  "from 0 to the largest field, per wavelength");
    cmd->add_option("--field-curve-points", args->field_curve_points,
                    "Fields of the field curves, evenly from 0 to the largest (default 11)")
        ->check(CLI::Range(2, 1001));
    cmd->add_flag(
        "--focal-shift", args->focal_shift,
        "Chromatic focal shift: the paraxial image position against wavelength over a band, "
        "from that at the primary wavelength");
    cmd->add_option("--band", args->band,
                    "The focal shift's band: two wavelengths in nm, comma-separated (default: "
                    "the shortest and longest of --wavelengths, else the F and C lines)")
        ->delimiter(',')
        ->check(CLI::PositiveNumber);
    cmd->add_option("--focal-shift-points", args->focal_shift_points,
                    "Wavelengths of the focal shift, evenly across the band (default 21)")
        ->check(CLI::Range(2, 10001));
    cmd->add_option("--wavelength-weights", args->wavelength_weights,
                    "Weights of --wavelengths, comma-separated, one each (default: equal): the "
                    "polychromatic spot radius weights each wavelength's rays by them")
        ->delimiter(',');
    cmd->add_option("--unit", args->unit,
                    "The scene's length unit, for the figures' labels (e.g. mm); a scene "
                    "declares none, so they say \"units\" without it");
    cmd->add_option(
        "--lens", args->lens,
        "Measure this lens (name or objects[i]) and the lenses on its axis; others are ignored");
    return [args] { return run(*args); };
}

}  // namespace lenslab::cli
