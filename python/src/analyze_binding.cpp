// lenslab.analyze: the optical bench's report, built from the library as `lenslab analyze
// --json` builds it (report_json), for the options a first-order study needs.

#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <vector>

#include "analysis/lens_lookup.h"
#include "analysis/lens_report.h"
#include "bindings.h"
#include "scene/json_reader.h"
#include "scene_bridge.h"

namespace lenslab::python {

namespace {

namespace py = pybind11;

struct AnalyzeOptions {
    double wavelength_nm = kLineD;
    std::string lens;
    int stop = 1;  // 1-based, as the command line counts surfaces
    double epd = 0, f_number = 0;
    std::vector<double> fields;
};

// The lens object `name` names (its name, its group's, or "objects[i]"), as --lens finds it.
int lens_index(const Scene& scene, const std::string& name) {
    const LensLookup lookup = find_lens(scene, name);
    if (!lookup.index) throw py::value_error("lens: " + no_lens_message(name, "the scene", lookup));
    return *lookup.index;
}

LensReportOptions report_options(const OpticalSystem& system, const AnalyzeOptions& a) {
    const int surfaces = static_cast<int>(system.surfaces.size());
    if (a.stop < 1 || a.stop > surfaces) {
        throw py::value_error("stop " + std::to_string(a.stop) + ": the system has " +
                              std::to_string(surfaces) + " surfaces, numbered 1 to " +
                              std::to_string(surfaces));
    }
    for (double angle : a.fields) {
        if (!(std::abs(angle) < 90.0)) {
            throw py::value_error("fields: " + format_number(angle) +
                                  " degrees is not a field angle (between -90 and 90)");
        }
    }
    LensReportOptions options;
    options.wavelength_nm = a.wavelength_nm;
    options.first_order.stop = a.stop - 1;
    options.first_order.epd = a.epd;
    options.first_order.f_number = a.f_number;
    if (!a.fields.empty()) options.first_order.fields = a.fields;
    return options;
}

std::string analyze_json(const std::string& json_text, const std::string& path,
                         const AnalyzeOptions& a) {
    py::gil_scoped_release unlocked;
    const Scene scene = build_scene(json_text, path, {.require_camera = false});
    const std::optional<int> lens =
        a.lens.empty() ? std::nullopt : std::optional<int>(lens_index(scene, a.lens));
    try {
        const OpticalSystem system = build_optical_system(scene, lens);
        nlohmann::ordered_json j =
            report_json(system, analyze_lens_system(system, report_options(system, a)));
        if (!path.empty()) j["scene"] = path;
        return j.dump();
    } catch (const SceneError& e) {
        // As the command line says it: a scene that loaded but is no lens system names its file.
        if (path.empty()) throw;
        throw SceneError(path + ": " + e.path(), e.reason());
    }
}

}  // namespace

void bind_analyze(py::module_& m) {
    m.def(
        "analyze",
        [](const std::string& json_text, const std::string& path, double wavelength,
           const std::string& lens, int stop, double epd, double f_number,
           const std::vector<double>& fields) {
            return analyze_json(json_text, path, {wavelength, lens, stop, epd, f_number, fields});
        },
        py::arg("json_text"), py::arg("path"), py::arg("wavelength"), py::arg("lens"),
        py::arg("stop"), py::arg("epd"), py::arg("f_number"), py::arg("fields"),
        "The report of `lenslab analyze --json`, as JSON text");
}

}  // namespace lenslab::python
