// lenslab.analyze's engine: analyze_scene (analysis/analyze_request.h), the work of `lenslab
// analyze`, kept as an AnalyzeRun whose document is the one `lenslab analyze --json` prints,
// whose figures are the SVG text the command line writes to files, and whose spot diagrams'
// ray hits come out as numpy arrays.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <regex>

#include "analysis/analyze_figures.h"
#include "analysis/analyze_request.h"
#include "bindings.h"
#include "scene/json_reader.h"
#include "scene_bridge.h"

namespace lenslab::python {

namespace {

namespace py = pybind11;
using nlohmann::json;

// The options as the Python module names them: "--image-distance" becomes "image_distance".
std::string python_names(const std::string& message) {
    static const std::regex option("--([a-z][a-z-]*)");
    std::string out;
    auto begin = message.cbegin();
    for (std::sregex_iterator it(message.begin(), message.end(), option), end; it != end; ++it) {
        out.append(begin, message.cbegin() + it->position());
        std::string name = (*it)[1].str();
        std::replace(name.begin(), name.end(), '-', '_');
        out += name;
        begin = message.cbegin() + it->position() + it->length();
    }
    out.append(begin, message.cend());
    return out;
}

template <class T>
void take(const json& j, const char* key, T& into) {
    if (j.contains(key) && !j[key].is_null()) into = j[key].get<T>();
}

// The request from the JSON object lenslab/_optics.py sends (its keys are the fields' names).
AnalyzeRequest request_from(const json& j) {
    AnalyzeRequest a;
    take(j, "wavelength_nm", a.wavelength_nm);
    a.wavelength_given = j.contains("wavelength_nm");
    take(j, "wavelengths", a.wavelengths);
    take(j, "aperture", a.aperture);
    take(j, "lens", a.lens);
    take(j, "unit", a.unit);
    take(j, "stop", a.stop);
    take(j, "epd", a.epd);
    take(j, "f_number", a.f_number);
    take(j, "object_distance", a.object_distance);
    take(j, "fields", a.fields);
    take(j, "field_heights", a.field_heights);
    take(j, "seidel", a.seidel);
    take(j, "psf", a.psf);
    take(j, "mtf", a.mtf);
    take(j, "mtf_frequencies", a.mtf_frequencies);
    take(j, "spots", a.spots);
    take(j, "rings", a.rings);
    if (j.contains("image_distance") && !j["image_distance"].is_null())
        a.image_distance = j["image_distance"].get<double>();
    take(j, "wavelength_weights", a.wavelength_weights);
    take(j, "fans", a.fans);
    take(j, "fan_points", a.fan_points);
    take(j, "field_curves", a.field_curves);
    take(j, "field_curve_points", a.field_curve_points);
    take(j, "focal_shift", a.focal_shift);
    take(j, "band", a.band);
    take(j, "focal_shift_points", a.focal_shift_points);
    take(j, "report", a.report_keys);
    return a;
}

// A finished analysis: the request, its results and the scene's file ("" for none).
struct AnalyzeRun {
    AnalyzeRequest request;
    AnalyzeResults results;
    std::string scene_file;
};

// The document, or only the keys of request.report_keys (in the document's order).
std::string document(const AnalyzeRun& run) {
    const nlohmann::ordered_json j = analyze_json(run.results, run.request, run.scene_file);
    for (const std::string& key : run.request.report_keys) {
        if (j.contains(key)) continue;
        std::string known;
        for (const std::string& name :
             analyze_json_keys(run.results, run.request, run.scene_file)) {
            known += (known.empty() ? "" : ", ") + name;
        }
        throw py::value_error("report: no key '" + key + "' in this analysis (keys: " + known +
                              ")");
    }
    return j.dump();
}

std::string figure(const AnalyzeRun& run, const std::string& name) {
    try {
        py::gil_scoped_release unlocked;
        return bench_figure_svg(run.results, run.request, name);
    } catch (const AnalyzeRequestError& e) {
        throw py::value_error(python_names(e.what()));
    }
}

// Per spot diagram (field and wavelength, in the order of the document's
// spots.per_wavelength): (field, wavelength in nm, the hits' (x, y) as an (N, 2) array).
py::list spot_points(const AnalyzeRun& run) {
    py::list out;
    if (!run.results.spots) return out;
    for (const FieldSpots& f : run.results.spots->fields) {
        for (const WavelengthSpot& s : f.spots) {
            const auto n = static_cast<py::ssize_t>(s.spot.points.size());
            py::array_t<double> xy({n, py::ssize_t{2}});
            auto at = xy.mutable_unchecked<2>();
            for (py::ssize_t i = 0; i < n; ++i) {
                at(i, 0) = s.spot.points[static_cast<size_t>(i)].x;
                at(i, 1) = s.spot.points[static_cast<size_t>(i)].y;
            }
            out.append(py::make_tuple(s.field, s.wavelength_nm, xy));
        }
    }
    return out;
}

AnalyzeRun analyze(const std::string& json_text, const std::string& path,
                   const std::string& request_json) {
    AnalyzeRun run;
    run.request = request_from(json::parse(request_json));
    run.scene_file = path;
    py::gil_scoped_release unlocked;
    const Scene scene =
        build_scene(json_text, path, {.require_camera = false, .build_for_rendering = false});
    try {
        run.results = analyze_scene(scene, run.request, path);
    } catch (const AnalyzeRequestError& e) {
        throw py::value_error(python_names(e.what()));
    }
    return run;
}

}  // namespace

void bind_analyze(py::module_& m) {
    py::class_<AnalyzeRun>(m, "AnalyzeRun", "A finished lenslab.analyze (use lenslab.Analysis)")
        .def("document", &document)
        .def("figure", &figure, py::arg("name"))
        .def("spot_points", &spot_points);
    m.def("analyze", &analyze, py::arg("json_text"), py::arg("path"), py::arg("request_json"),
          "Runs `lenslab analyze` on the scene with the request (JSON of AnalyzeRequest's "
          "fields)");
    m.attr("FIGURES") = bench_figure_names();
}

}  // namespace lenslab::python
