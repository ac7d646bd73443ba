// lenslab.trace: the tree of one ray's paths, as `lenslab trace` prints it (the same JSON,
// handed to Python as text and parsed there).

#include <pybind11/stl.h>

#include <array>

#include "analysis/trace/ray_tree.h"
#include "bindings.h"
#include "optics/spectrum.h"
#include "scene/json_reader.h"
#include "scene_bridge.h"

namespace lenslab::python {

namespace {

namespace py = pybind11;

std::string trace_json(const std::string& json_text, const std::string& path,
                       const std::array<double, 3>& origin, const std::array<double, 3>& direction,
                       const RayTreeOptions& options) {
    const Vec3 d{direction[0], direction[1], direction[2]};
    if (!(length(d) > 0)) throw py::value_error("direction: must be a non-zero vector");
    // The ranges `lenslab trace` accepts for its options.
    const auto check = [](const char* name, double v, double low, double high) {
        if (!(v >= low && v <= high)) {
            throw py::value_error(std::string(name) + ": " + format_number(v) +
                                  " is not in the range " + format_number(low) + " to " +
                                  format_number(high));
        }
    };
    check("wavelength", options.wavelength_nm, kLambdaMinNm, 2500.0);
    check("max_depth", options.max_depth, 0, 1000);
    check("min_weight", options.min_weight, kMinBranchWeight, 1.0);
    py::gil_scoped_release unlocked;
    const Scene scene = build_scene(json_text, path);
    const Ray ray{{origin[0], origin[1], origin[2]}, normalize(d)};
    return to_json(scene, trace_ray_tree(scene, ray, options)).dump();
}

}  // namespace

void bind_trace(py::module_& m) {
    m.def(
        "trace",
        [](const std::string& json_text, const std::string& path,
           const std::array<double, 3>& origin, const std::array<double, 3>& direction,
           double wavelength, int max_depth, double min_weight) {
            RayTreeOptions options;
            options.wavelength_nm = wavelength;
            options.max_depth = max_depth;
            options.min_weight = min_weight;
            return trace_json(json_text, path, origin, direction, options);
        },
        py::arg("json_text"), py::arg("path"), py::arg("origin"), py::arg("direction"),
        py::arg("wavelength"), py::arg("max_depth"), py::arg("min_weight"),
        "The ray tree as JSON text (the keys of `lenslab trace`)");
    const RayTreeOptions defaults;
    m.attr("TRACE_MAX_DEPTH") = defaults.max_depth;
    m.attr("TRACE_MIN_WEIGHT") = defaults.min_weight;
    m.attr("LINE_D") = kLineD;
}

}  // namespace lenslab::python
