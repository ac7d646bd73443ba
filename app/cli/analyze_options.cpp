#include "analyze_options.h"

#include "commands.h"

namespace lenslab::cli {

void add_analyze_options(CLI::App& cmd, AnalyzeRequest& request) {
    CLI::Option* wavelength =
        cmd.add_option("-w,--wavelength", request.wavelength_nm,
                       "Wavelength in air in nm for the figures (default: the d line, 587.56 "
                       "nm; in vacuum for a scene with \"ambient\": \"vacuum\"; an imported "
                       "lens file's wavelengths when its scene has them)")
            ->check(CLI::PositiveNumber)
            ->each([&request](const std::string&) { request.wavelength_given = true; });
    cmd.add_option("--wavelengths", request.wavelengths,
                   "Wavelengths in nm, comma-separated (e.g. 486.1327,587.5618,656.2725): the "
                   "middle one is the primary, for every single-wavelength figure; the "
                   "shortest and longest give the chromatic block and the Seidel colour sums "
                   "(default: the F and C lines)")
        ->delimiter(',')
        ->check(CLI::PositiveNumber)
        ->excludes(wavelength);
    cmd.add_flag("--json", request.json, "Print the figures as JSON");
    cmd.add_option("--svg", request.svg,
                   "Write a ray diagram to this file: SVG, or PNG for a name ending in .png");
    CLI::Option* aperture =
        cmd.add_option("--aperture", request.aperture,
                       "Diameter of the collimated beam, in the scene's unit (default: all the "
                       "lens passes)")
            ->check(CLI::PositiveNumber);
    cmd.add_option("--stop", request.stop,
                   "The aperture stop: a surface, counted from 1 along the light (default: an "
                   "imported lens file's stop, else 1, the first surface)")
        ->check(whole_number<int>())
        ->check(CLI::PositiveNumber);
    cmd.add_option_function<std::string>(
           "--ray-aiming",
           [&request](const std::string& name) { request.ray_aiming = ray_aiming_named(name); },
           "How real rays are aimed at a pupil point: real (through the real stop) or paraxial "
           "(at the paraxial entrance pupil, Zemax's default) (default: an imported lens file's, "
           "else real)")
        ->check(CLI::IsMember({"real", "paraxial"}));
    CLI::Option* epd =
        cmd.add_option("--epd", request.epd,
                       "Entrance pupil diameter (default: the beam of --aperture with the stop "
                       "on the first surface, else the stop surface's rim)")
            ->check(CLI::PositiveNumber)
            ->excludes(aperture);
    cmd.add_option("--f-number", request.f_number,
                   "F-number: sets the entrance pupil diameter to EFL / N")
        ->check(CLI::PositiveNumber)
        ->excludes(aperture)
        ->excludes(epd);
    CLI::Option* distance =
        cmd.add_option("--object-distance", request.object_distance,
                       "Distance from the object to the first vertex (default: the object at "
                       "infinity)")
            ->check(CLI::PositiveNumber);
    cmd.add_option("--fields", request.fields,
                   "Field angles in degrees, comma-separated, for an object at infinity "
                   "(default: 0); the chief ray comes from the largest")
        ->delimiter(',')
        ->excludes(distance);
    cmd.add_option("--field-heights", request.field_heights,
                   "Object heights, comma-separated, for an object at --object-distance")
        ->delimiter(',')
        ->needs(distance);
    cmd.add_flag("--seidel", request.seidel,
                 "Print the Seidel sums surface by surface (JSON always has them)");
    cmd.add_flag(
        "--psf", request.psf,
        "Diffraction on the axis at the primary wavelength: the point spread function's "
        "Strehl ratio, wavefront RMS and encircled energy at the best focus (lengths in mm)");
    cmd.add_flag(
        "--mtf", request.mtf,
        "Diffraction MTF on the axis at the primary wavelength, tangential and sagittal, beside "
        "the diffraction limit (frequencies in cycles/mm)");
    cmd.add_option("--mtf-frequencies", request.mtf_frequencies,
                   "Frequencies of the MTF in cycles/mm, comma-separated (default: ten up to "
                   "the cutoff 1/(lambda N))")
        ->delimiter(',')
        ->check(CLI::PositiveNumber);
    cmd.add_flag(
        "--spots", request.spots,
        "Spot diagrams per field and wavelength: RMS and geometric radii about the centroid, "
        "chief ray, vignetting, and per field the polychromatic RMS beside the Airy radius");
    cmd.add_option("--rings", request.rings,
                   "Hexapolar rings of the spot diagrams' beams, Zemax's \"ray density\": 1 + "
                   "3 N (N + 1) rays (default 6: 127)")
        ->check(CLI::Range(1, 200));
    cmd.add_option("--field-map", request.field_map,
                   "RMS spot radius over an N x N grid of field points in x and y, out to the "
                   "largest of --fields (odd N puts one on the axis)")
        ->check(CLI::Range(1, 101));
    cmd.add_flag(
        "--fans", request.fans,
        "Transverse ray fans per field and wavelength, tangential (e_y against py) and sagittal "
        "(e_x against px), from the primary wavelength's chief ray");
    cmd.add_option("--spots-svg", request.spots_svg,
                   "Write the spot diagrams to this file, SVG or (.png) PNG; implies --spots");
    cmd.add_option("--fans-svg", request.fans_svg,
                   "Write the ray fans to this file, SVG or (.png) PNG; implies --fans");
    cmd.add_option("--curves-svg", request.curves_svg,
                   "Write the field curves (field curvature and distortion) to this file, SVG or "
                   "(.png) PNG; implies --field-curves");
    cmd.add_option("--focal-shift-svg", request.focal_shift_svg,
                   "Write the chromatic focal shift to this file, SVG or (.png) PNG; implies "
                   "--focal-shift");
    cmd.add_option("--mtf-svg", request.mtf_svg,
                   "Write the MTF on the axis beside the diffraction limit to this file, SVG or "
                   "(.png) PNG; implies --mtf");
    cmd.add_option("--fan-points", request.fan_points,
                   "Points along each ray fan, evenly from -1 to 1 across the stop (default 21)")
        ->check(CLI::Range(2, 10001));
    cmd.add_option("--image-distance", request.image_distance,
                   "The image plane of the spots, fans and field curves, from the last vertex "
                   "(default: the "
                   "paraxial image plane at the primary wavelength)");
    cmd.add_flag("--field-curves", request.field_curves,
                 "Tangential and sagittal field curvature and real distortion against field, "
                 "from 0 to the largest field, per wavelength");
    cmd.add_option("--field-curve-points", request.field_curve_points,
                   "Fields of the field curves, evenly from 0 to the largest (default 11)")
        ->check(CLI::Range(2, 1001));
    cmd.add_flag(
        "--focal-shift", request.focal_shift,
        "Chromatic focal shift: the paraxial image position against wavelength over a band, "
        "from that at the primary wavelength");
    cmd.add_option("--band", request.band,
                   "The focal shift's band: two wavelengths in nm, comma-separated (default: "
                   "the shortest and longest of --wavelengths, else the F and C lines)")
        ->delimiter(',')
        ->check(CLI::PositiveNumber);
    cmd.add_option("--focal-shift-points", request.focal_shift_points,
                   "Wavelengths of the focal shift, evenly across the band (default 21)")
        ->check(CLI::Range(2, 10001));
    cmd.add_option("--wavelength-weights", request.wavelength_weights,
                   "Weights of --wavelengths, comma-separated, one each (default: equal): the "
                   "polychromatic spot radius weights each wavelength's rays by them")
        ->delimiter(',');
    cmd.add_option("--unit", request.unit,
                   "The scene's length unit, for the figures' labels (e.g. mm); a scene "
                   "declares none, so they say \"units\" without it");
    cmd.add_option(
        "--lens", request.lens,
        "Measure this lens (name or objects[i]) and the lenses on its axis; others are ignored");
}

}  // namespace lenslab::cli
