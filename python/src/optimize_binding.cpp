// lenslab.optimize and lenslab.tolerance's engines: optimize_design and tolerance_design, as
// `lenslab optimize` and `lenslab tolerance` run them, each as a BackgroundJob
// (background_job.h): progress delivered to Python, Ctrl-C stopping the work.

#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "background_job.h"
#include "bindings.h"
#include "optimize/global_search.h"
#include "optimize/lens_design.h"
#include "optimize/optimize_design.h"
#include "optimize/optimize_report.h"
#include "optimize/tolerance.h"
#include "optimize/tolerance_report.h"

namespace py = pybind11;

namespace lenslab::python {

namespace {

// Thrown from a progress callback to stop the work once Python has stopped waiting for it.
struct Stopped {};

// The design in `design_json` (a design file's text); relative paths in it resolve against
// `base_dir`. An inline system keeps its keys' order in the written scene, as the command
// line's does.
LensDesign design_of(const std::string& design_json, const std::string& base_dir) {
    LensDesign design = lens_design_from_json(nlohmann::json::parse(design_json), base_dir);
    if (design.system_file.empty())
        design.scene = nlohmann::ordered_json::parse(design_json)["system"];
    return design;
}

// The optimised scene's JSON text and the report's (`lenslab optimize --json`'s).
std::pair<std::string, std::string> optimize(const std::string& design_json,
                                             const std::string& base_dir, int iterations,
                                             int global_starts, const py::object& progress) {
    LensDesign design = [&] {
        py::gil_scoped_release unlocked;
        return design_of(design_json, base_dir);
    }();
    if (global_starts >= 0) design.global_search.starts = global_starts;
    const int whole = iterations >= 0 ? iterations : design.iterations;
    const double total = design.global_search.starts > 0
                             ? double(global_search_runs(design.global_search))
                             : double(std::max(whole, 1));
    BackgroundJob<OptimizeResult> job([&design, iterations, total](RenderControl& control) {
        return optimize_design(design, iterations, [&control, total](const LmProgress& p) {
            if (control.cancelled()) throw Stopped{};
            control.report(std::min(1.0, p.iteration / total));
        });
    });
    const OptimizeResult result = job.run(progress);
    nlohmann::ordered_json report = optimize_json(result);
    // A multi-configuration design's other configurations, made Scenes on the Python side.
    for (const auto& [name, scene] : result.configuration_scenes) {
        report["configuration_scenes"][name] = scene;
    }
    return {result.scene.dump(), report.dump()};
}

// The report's JSON text (`lenslab tolerance --json`'s).
std::string tolerance(const std::string& design_json, const std::string& base_dir, int trials,
                      int64_t seed, const py::object& progress) {
    LensDesign design = [&] {
        py::gil_scoped_release unlocked;
        return design_of(design_json, base_dir);
    }();
    if (trials > 0) design.tolerances.trials = trials;
    if (seed >= 0) design.tolerances.seed = uint64_t(seed);
    BackgroundJob<ToleranceReport> job([&design](RenderControl& control) {
        return tolerance_design(design, [&control](int done, int of) {
            if (control.cancelled()) throw Stopped{};
            control.report(double(done) / of);
        });
    });
    return tolerance_json(job.run(progress)).dump();
}

}  // namespace

void bind_optimize(py::module_& m) {
    m.def("optimize", &optimize, py::arg("design_json"), py::arg("base_dir"), py::arg("iterations"),
          py::arg("global_starts"), py::arg("progress"),
          "Optimises a lens design as `lenslab optimize` does: (scene JSON, report JSON); "
          "iterations or global_starts < 0: the design's");
    m.def("tolerance", &tolerance, py::arg("design_json"), py::arg("base_dir"), py::arg("trials"),
          py::arg("seed"), py::arg("progress"),
          "Tolerances a lens design as `lenslab tolerance` does: the report's JSON; trials <= 0 "
          "or seed < 0: the design's");
}

}  // namespace lenslab::python
