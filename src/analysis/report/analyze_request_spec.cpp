#include "analysis/report/analyze_request_spec.h"

#include <algorithm>

namespace lenslab {

namespace {

using nlohmann::json;
using Request = AnalyzeRequest;

// An option's name, kind of value and help; its set and get still to be given.
RequestOption declared(std::string name, RequestValue value, std::string help) {
    RequestOption o;
    o.name = std::move(name);
    o.value = value;
    o.help = std::move(help);
    return o;
}

template <class T>
RequestOption member_option(std::string name, RequestValue value, T Request::*member,
                            std::string help) {
    RequestOption o = declared(std::move(name), value, std::move(help));
    o.set = [member](Request& r, const json& j) { r.*member = j.get<T>(); };
    o.get = [member](const Request& r) { return json(r.*member); };
    return o;
}

RequestOption flag(std::string name, bool Request::*member, std::string help) {
    return member_option(std::move(name), RequestValue::Flag, member, std::move(help));
}

RequestOption whole(std::string name, int Request::*member, int low, int high, std::string help) {
    RequestOption o = member_option(std::move(name), RequestValue::Whole, member, std::move(help));
    o.low = low;
    o.high = high;
    return o;
}

RequestOption figure_file(std::string name, std::string Request::*member, std::string help) {
    RequestOption o = member_option(std::move(name), RequestValue::Text, member, std::move(help));
    o.where = RequestWhere::CommandLine;
    return o;
}

RequestOption needing(RequestOption o, std::string other, std::string why) {
    o.needs = std::move(other);
    o.needs_why = std::move(why);
    return o;
}

RequestOption excluding(RequestOption o, std::vector<std::string> others, std::string why) {
    o.excludes = std::move(others);
    o.excludes_why = std::move(why);
    return o;
}

std::vector<RequestOption> declare_options() {
    std::vector<RequestOption> all;
    RequestOption wavelength = declared(
        "wavelength", RequestValue::PositiveNumber,
        "Wavelength in air in nm for the figures (default: the d line, 587.56 nm; in vacuum "
        "for a scene with \"ambient\": \"vacuum\"; an imported lens file's wavelengths when its "
        "scene has them)");
    wavelength.short_name = "w";
    // Given, it wins over an imported lens file's wavelengths.
    wavelength.set = [](Request& r, const json& j) {
        r.wavelength_nm = j.get<double>();
        r.wavelength_given = true;
    };
    wavelength.get = [](const Request& r) {
        return r.wavelength_given ? json(r.wavelength_nm) : json();
    };
    all.push_back(wavelength);
    all.push_back(excluding(
        member_option("wavelengths", RequestValue::PositiveNumbers, &Request::wavelengths,
                      "Wavelengths in nm, comma-separated (e.g. 486.1327,587.5618,656.2725): the "
                      "middle one is the primary, for every single-wavelength figure; the "
                      "shortest and longest give the chromatic block and the Seidel colour sums "
                      "(default: the F and C lines)"),
        {"wavelength"}, "the primary is the middle one"));
    RequestOption json_output = flag("json", &Request::json, "Print the figures as JSON");
    json_output.where = RequestWhere::CommandLine;
    all.push_back(json_output);
    all.push_back(
        figure_file("svg", &Request::svg,
                    "Write a ray diagram to this file: SVG, or PNG for a name ending in .png"));
    all.push_back(member_option("aperture", RequestValue::PositiveNumber, &Request::aperture,
                                "Diameter of the collimated beam, in the scene's unit (default: "
                                "all the lens passes)"));
    all.push_back(whole("stop", &Request::stop, 1, 100000,
                        "The aperture stop: a surface, counted from 1 along the light "
                        "(default: an imported lens file's stop, else 1, the first surface)"));
    RequestOption aiming = declared(
        "ray-aiming", RequestValue::Choice,
        "How real rays are aimed at a pupil point: real (through the real stop) or paraxial "
        "(at the paraxial entrance pupil, Zemax's default) (default: an imported lens file's, "
        "else real)");
    aiming.choices = {ray_aiming_name(RayAiming::Real), ray_aiming_name(RayAiming::Paraxial)};
    aiming.set = [](Request& r, const json& j) {
        r.ray_aiming = ray_aiming_named(j.get<std::string>());
    };
    aiming.get = [](const Request& r) {
        return r.ray_aiming ? json(ray_aiming_name(*r.ray_aiming)) : json();
    };
    all.push_back(aiming);
    all.push_back(excluding(
        member_option("epd", RequestValue::PositiveNumber, &Request::epd,
                      "Entrance pupil diameter (default: the beam of --aperture with the stop on "
                      "the first surface, else the stop surface's rim)"),
        {"aperture"}, "both set the entrance pupil"));
    all.push_back(
        excluding(member_option("f-number", RequestValue::PositiveNumber, &Request::f_number,
                                "F-number: sets the entrance pupil diameter to EFL / N"),
                  {"aperture", "epd"}, "both set the entrance pupil"));
    all.push_back(member_option("object-distance", RequestValue::PositiveNumber,
                                &Request::object_distance,
                                "Distance from the object to the first vertex (default: the "
                                "object at infinity)"));
    all.push_back(excluding(
        member_option("fields", RequestValue::Numbers, &Request::fields,
                      "Field angles in degrees, comma-separated, for an object at infinity "
                      "(default: 0); the chief ray comes from the largest"),
        {"object-distance"}, "field angles are for an object at infinity; use field-heights"));
    all.push_back(needing(
        member_option("field-heights", RequestValue::Numbers, &Request::field_heights,
                      "Object heights, comma-separated, for an object at --object-distance"),
        "object-distance", "heights of an object at a finite distance"));
    all.push_back(flag("seidel", &Request::seidel,
                       "Print the Seidel sums surface by surface (JSON always has them)"));
    all.push_back(flag(
        "psf", &Request::psf,
        "Diffraction on the axis at the primary wavelength: the point spread function's Strehl "
        "ratio, wavefront RMS and encircled energy at the best focus; and per field the "
        "polychromatic PSF in that plane (or --image-distance): Strehl, centroid, encircled and "
        "ensquared energy, the image (lengths in mm)"));
    all.push_back(
        flag("mtf", &Request::mtf,
             "Diffraction MTF at every field, tangential and sagittal, polychromatic over the "
             "wavelengths (weighted by --wavelength-weights), beside the diffraction limit, at the "
             "axial best focus or --image-distance (frequencies in cycles/mm)"));
    all.push_back(
        flag("wavefront", &Request::wavefront,
             "The wavefront at each field and wavelength from real rays, against the chief ray's "
             "reference sphere in the image plane: RMS, peak-to-valley, Strehl ratio, Zernike "
             "coefficients (Noll and Fringe) and the OPD map over the pupil, in waves"));
    all.push_back(needing(whole("zernike-terms", &Request::zernike_terms, 1, 231,
                                "Noll Zernike terms fitted to each wavefront (default 37; the "
                                "Fringe fit stops at its 37)"),
                          "wavefront", "the terms of the wavefront's fit"));
    all.push_back(needing(whole("wavefront-samples", &Request::wavefront_samples, 8, 512,
                                "Rays across the pupil's diameter for each wavefront, even "
                                "(default 64)"),
                          "wavefront", "the sampling of the wavefront's pupil"));
    RequestOption reference =
        declared("wavefront-reference", RequestValue::Choice,
                 "Where the wavefront's reference sphere is centred: chief (the chief ray's image "
                 "point, the default) or centroid (the PSF's centroid: the tilt taken out)");
    reference.choices = {"chief", "centroid"};
    reference.set = [](Request& r, const json& j) { r.wavefront_reference = j.get<std::string>(); };
    reference.get = [](const Request& r) {
        return r.wavefront_reference.empty() ? json() : json(r.wavefront_reference);
    };
    all.push_back(needing(reference, "wavefront", "the reference of the wavefront"));
    all.push_back(member_option("mtf-frequencies", RequestValue::PositiveNumbers,
                                &Request::mtf_frequencies,
                                "Frequencies of the MTF in cycles/mm, comma-separated (default: "
                                "ten up to the cutoff 1/(lambda N))"));
    all.push_back(member_option("through-focus", RequestValue::PositiveNumber,
                                &Request::through_focus,
                                "The MTF at this frequency (cycles/mm) through focus: every "
                                "field, tangential and sagittal, polychromatic, at planes about "
                                "the MTF's"));
    all.push_back(needing(member_option("through-focus-range", RequestValue::PositiveNumber,
                                        &Request::through_focus_range,
                                        "Half the through-focus range along the axis (default: one "
                                        "wave of defocus, 8 lambda N^2)"),
                          "through-focus", "the range of the through-focus MTF"));
    all.push_back(needing(whole("through-focus-points", &Request::through_focus_points, 3, 201,
                                "Image planes of the through-focus MTF, evenly across the range "
                                "(default 11)"),
                          "through-focus", "the planes of the through-focus MTF"));
    all.push_back(
        flag("spots", &Request::spots,
             "Spot diagrams per field and wavelength: RMS and geometric radii about the centroid, "
             "chief ray, vignetting, and per field the polychromatic RMS beside the Airy radius"));
    all.push_back(whole("rings", &Request::rings, 1, 200,
                        "Hexapolar rings of the spot diagrams' beams, Zemax's \"ray density\": "
                        "1 + 3 N (N + 1) rays (default 6: 127)"));
    all.push_back(whole("field-map", &Request::field_map, 0, 101,
                        "RMS spot radius over an N x N grid of field points in x and y, out to "
                        "the largest of --fields (odd N puts one on the axis; 0: none)"));
    all.push_back(flag(
        "fans", &Request::fans,
        "Transverse ray fans per field and wavelength, tangential (e_y against py) and sagittal "
        "(e_x against px), from the primary wavelength's chief ray"));
    all.push_back(flag("opd-fans", &Request::opd_fans,
                       "OPD fans per field and wavelength: the wavefront's optical path "
                       "difference along py (tangential) and px (sagittal), in waves against "
                       "each wavelength's chief ray and reference sphere"));
    all.push_back(figure_file("opd-fans-svg", &Request::opd_fans_svg,
                              "Write the OPD fans to this file, SVG or (.png) PNG; implies "
                              "--opd-fans"));
    all.push_back(
        figure_file("spots-svg", &Request::spots_svg,
                    "Write the spot diagrams to this file, SVG or (.png) PNG; implies --spots"));
    all.push_back(
        figure_file("fans-svg", &Request::fans_svg,
                    "Write the ray fans to this file, SVG or (.png) PNG; implies --fans"));
    all.push_back(figure_file("curves-svg", &Request::curves_svg,
                              "Write the field curves (field curvature and distortion) to this "
                              "file, SVG or (.png) PNG; implies --field-curves"));
    all.push_back(figure_file("focal-shift-svg", &Request::focal_shift_svg,
                              "Write the chromatic focal shift to this file, SVG or (.png) PNG; "
                              "implies --focal-shift"));
    all.push_back(figure_file("mtf-svg", &Request::mtf_svg,
                              "Write the MTF of every field beside the diffraction limit to this "
                              "file, SVG or (.png) PNG; implies --mtf"));
    all.push_back(flag("psf-huygens", &Request::psf_huygens,
                       "Find the PSF of every field by Huygens' wavelets from the reference "
                       "sphere (exact distances, no Fraunhofer approximation; slower) instead of "
                       "the Fourier transform"));
    all.push_back(figure_file("psf-png", &Request::psf_png,
                              "Write the polychromatic PSF of every field to this PNG file, false "
                              "colour on one scale; implies --psf"));
    RequestOption psf_log = flag("psf-log", &Request::psf_log,
                                 "Draw --psf-png on a log scale (four decades below the peak)");
    psf_log.where = RequestWhere::CommandLine;
    all.push_back(psf_log);
    all.push_back(figure_file("opd-png", &Request::opd_png,
                              "Write the OPD map of every field at the primary wavelength to this "
                              "PNG file; implies --wavefront"));
    all.push_back(
        whole("fan-points", &Request::fan_points, 2, 10001,
              "Points along each ray fan and OPD fan, evenly from -1 to 1 across the stop "
              "(default 21)"));
    RequestOption image_distance = declared(
        "image-distance", RequestValue::Number,
        "The image plane of the spots, fans, field curves, wavefronts and MTF, from the last "
        "vertex (default: the paraxial image plane at the primary wavelength; the MTF's: the "
        "axial best focus)");
    image_distance.set = [](Request& r, const json& j) { r.image_distance = j.get<double>(); };
    image_distance.get = [](const Request& r) {
        return r.image_distance ? json(*r.image_distance) : json();
    };
    all.push_back(image_distance);
    all.push_back(flag("field-curves", &Request::field_curves,
                       "Tangential and sagittal field curvature and real distortion against "
                       "field, from 0 to the largest field, per wavelength"));
    all.push_back(whole("field-curve-points", &Request::field_curve_points, 2, 1001,
                        "Fields of the field curves, evenly from 0 to the largest (default 11)"));
    all.push_back(flag("focal-shift", &Request::focal_shift,
                       "Chromatic focal shift: the paraxial image position against wavelength "
                       "over a band, from that at the primary wavelength"));
    all.push_back(member_option("band", RequestValue::PositiveNumbers, &Request::band,
                                "The focal shift's band: two wavelengths in nm, comma-separated "
                                "(default: the shortest and longest of --wavelengths, else the F "
                                "and C lines)"));
    all.push_back(whole("focal-shift-points", &Request::focal_shift_points, 2, 10001,
                        "Wavelengths of the focal shift, evenly across the band (default 21)"));
    all.push_back(member_option("wavelength-weights", RequestValue::Numbers,
                                &Request::wavelength_weights,
                                "Weights of --wavelengths, comma-separated, one each (default: "
                                "equal): the polychromatic spot radius weights each "
                                "wavelength's rays by them"));
    all.push_back(member_option("unit", RequestValue::Text, &Request::unit,
                                "The scene's length unit, for the figures' labels (e.g. mm); a "
                                "scene declares none, so they say \"units\" without it"));
    all.push_back(member_option("lens", RequestValue::Text, &Request::lens,
                                "Measure this lens (name or objects[i]) and the lenses on its "
                                "axis; others are ignored"));
    RequestOption report =
        member_option("report", RequestValue::Texts, &Request::report_keys,
                      "Only these top-level keys of the document (e.g. efl, rms_spot_best); "
                      "only what they need is computed");
    report.where = RequestWhere::Python;
    all.push_back(report);
    return all;
}

std::string python_spelling(std::string name) {
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
}

const char* value_name(RequestValue v) {
    switch (v) {
        case RequestValue::Flag:
            return "flag";
        case RequestValue::Number:
            return "number";
        case RequestValue::PositiveNumber:
            return "positive_number";
        case RequestValue::Whole:
            return "whole";
        case RequestValue::Numbers:
            return "numbers";
        case RequestValue::PositiveNumbers:
            return "positive_numbers";
        case RequestValue::Text:
            return "text";
        case RequestValue::Texts:
            return "texts";
        case RequestValue::Choice:
            return "choice";
    }
    return "";
}

}  // namespace

std::string RequestOption::python_name() const { return python_spelling(name); }

nlohmann::json RequestOption::python_default() const {
    const nlohmann::json unset = get(AnalyzeRequest{});
    if (value == RequestValue::Flag) return unset;
    // A whole number's default is Python's when it is one of the values the option takes
    // (rings 6); one outside them means "not given" (stop 0: the lens file's), as None does.
    if (value == RequestValue::Whole && unset >= low && unset <= high) return unset;
    return nullptr;
}

const std::vector<RequestOption>& analyze_request_options() {
    static const std::vector<RequestOption> options = declare_options();
    return options;
}

const RequestOption* find_request_option(const std::string& name) {
    for (const RequestOption& o : analyze_request_options())
        if (o.name == name) return &o;
    return nullptr;
}

nlohmann::ordered_json analyze_request_options_json() {
    nlohmann::ordered_json all = nlohmann::ordered_json::array();
    for (const RequestOption& o : analyze_request_options()) {
        if (o.where == RequestWhere::CommandLine) continue;
        nlohmann::ordered_json j;
        j["name"] = o.python_name();
        j["option"] = "--" + o.name;
        j["value"] = value_name(o.value);
        j["default"] = o.python_default();
        j["help"] = o.help;
        if (o.value == RequestValue::Whole) {
            j["low"] = o.low;
            j["high"] = o.high;
        }
        if (!o.choices.empty()) j["choices"] = o.choices;
        if (!o.excludes.empty()) {
            std::vector<std::string> names;
            for (const std::string& e : o.excludes) names.push_back(python_spelling(e));
            j["excludes"] = names;
            j["excludes_why"] = python_spelling(o.excludes_why);
        }
        if (!o.needs.empty()) {
            j["needs"] = python_spelling(o.needs);
            j["needs_why"] = o.needs_why;
        }
        all.push_back(j);
    }
    return all;
}

AnalyzeRequest analyze_request_from_json(const nlohmann::json& values) {
    AnalyzeRequest request;
    for (const auto& [key, value] : values.items()) {
        const RequestOption* o = nullptr;
        for (const RequestOption& candidate : analyze_request_options())
            if (candidate.where != RequestWhere::CommandLine && candidate.python_name() == key)
                o = &candidate;
        if (!o) throw AnalyzeRequestError(key + ": not an option of the analysis");
        if (!value.is_null()) o->set(request, value);
    }
    return request;
}

}  // namespace lenslab
