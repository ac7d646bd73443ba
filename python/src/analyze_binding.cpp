// lenslab.analyze's engine: analyze_scene (analysis/report/analyze_request.h), the work of `lenslab
// analyze`, kept as an AnalyzeRun whose document is the one `lenslab analyze --json` prints,
// whose figures are the SVG text the command line writes to files, and whose spot diagrams'
// ray hits come out as numpy arrays. lenslab.analyze_many runs it on a list of scenes across
// the cores, as a BackgroundJob (background_job.h) so that Ctrl-C cancels it.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <optional>
#include <regex>
#include <thread>
#include <vector>

#include "analysis/figures/analyze_figures.h"
#include "analysis/report/analyze_request.h"
#include "analysis/report/analyze_request_spec.h"
#include "background_job.h"
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

// The request from the JSON object lenslab/_optics.py sends: Python's keywords, checked there
// against the declarations (analyze_request_options_json).
AnalyzeRequest request_from(const std::string& request_json) {
    try {
        return analyze_request_from_json(json::parse(request_json));
    } catch (const AnalyzeRequestError& e) {
        throw py::value_error(e.what());
    }
}

// A finished analysis: the request, its results and the scene's file ("" for none); the
// document's text where analyze_many's workers wrote it ("" until then).
struct AnalyzeRun {
    AnalyzeRequest request;
    AnalyzeResults results;
    std::string scene_file;
    std::string document;
};

// The document, or only the keys of request.report_keys (in the document's order).
std::string document_text(const AnalyzeRun& run) {
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

std::string document(const AnalyzeRun& run) {
    return run.document.empty() ? document_text(run) : run.document;
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

// The analysis of one scene; called without the GIL.
AnalyzeRun analyze_text(const std::string& json_text, const std::string& path,
                        const AnalyzeRequest& request) {
    AnalyzeRun run{.request = request, .results = {}, .scene_file = path, .document = {}};
    const Scene scene =
        build_scene(json_text, path, {.require_camera = false, .build_for_rendering = false});
    try {
        run.results = analyze_scene(scene, run.request, path);
    } catch (const AnalyzeRequestError& e) {
        throw py::value_error(python_names(e.what()));
    }
    return run;
}

AnalyzeRun analyze(const std::string& json_text, const std::string& path,
                   const std::string& request_json) {
    const AnalyzeRequest request = request_from(request_json);
    py::gil_scoped_release unlocked;
    return analyze_text(json_text, path, request);
}

// analyze_many's answer: the runs in the order of the scenes, or the first scene in that order
// that failed and its exception (the Python side names the scene in the message).
struct AnalyzeBatch {
    std::vector<AnalyzeRun> runs;
    std::optional<size_t> failed;
    std::exception_ptr error;
};

// The scenes on `threads` workers (0: one per core), each taking the next scene by an atomic
// index. A failure stops the scenes after it from starting; those before it were all taken
// already and finish, so the failure kept is the first in the list's order whatever the timing.
AnalyzeBatch analyze_all(const std::vector<std::string>& texts,
                         const std::vector<std::string>& paths, const AnalyzeRequest& request,
                         int threads, RenderControl& control) {
    const size_t n = texts.size();
    AnalyzeBatch batch;
    batch.runs.resize(n);
    std::vector<std::exception_ptr> errors(n);
    std::atomic<size_t> next{0};
    std::atomic<size_t> done{0};
    std::atomic<size_t> first_failed{n};
    auto work = [&] {
        for (size_t i = next++; i < n && !control.cancelled(); i = next++) {
            if (i > first_failed.load()) break;
            try {
                AnalyzeRun& run = batch.runs[i];
                run = analyze_text(texts[i], paths[i], request);
                run.document = document_text(run);  // here, on the workers, not under the GIL
            } catch (...) {
                errors[i] = std::current_exception();
                for (size_t seen = first_failed.load();
                     i < seen && !first_failed.compare_exchange_weak(seen, i);) {
                }
            }
            control.report(static_cast<double>(++done) / static_cast<double>(n));
        }
    };
    const size_t cores = std::max(1U, std::thread::hardware_concurrency());
    const size_t workers = std::min(threads > 0 ? static_cast<size_t>(threads) : cores, n);
    {
        std::vector<std::jthread> helpers;
        for (size_t w = 1; w < workers; ++w) helpers.emplace_back(work);
        work();
    }
    if (first_failed.load() < n) {
        batch.failed = first_failed.load();
        batch.error = errors[*batch.failed];
    }
    return batch;
}

AnalyzeBatch analyze_many(const std::vector<std::string>& texts,
                          const std::vector<std::string>& paths, const std::string& request_json,
                          int threads, const py::object& progress) {
    if (texts.size() != paths.size()) throw py::value_error("as many paths as scenes, please");
    const AnalyzeRequest request = request_from(request_json);
    BackgroundJob<AnalyzeBatch> job([&](RenderControl& control) {
        return analyze_all(texts, paths, request, threads, control);
    });
    return job.run(progress);  // Ctrl-C or an exception from progress cancels the rest
}

py::list batch_runs(AnalyzeBatch& batch) {
    py::list out;
    for (AnalyzeRun& run : batch.runs) out.append(py::cast(std::move(run)));
    batch.runs.clear();
    return out;
}

void raise_failure(const AnalyzeBatch& batch) {
    if (batch.error) std::rethrow_exception(batch.error);
}

}  // namespace

void bind_analyze(py::module_& m) {
    py::class_<AnalyzeRun>(m, "AnalyzeRun", "A finished lenslab.analyze (use lenslab.Analysis)")
        .def("document", &document)
        .def("figure", &figure, py::arg("name"))
        .def("spot_points", &spot_points);
    m.def("analyze", &analyze, py::arg("json_text"), py::arg("path"), py::arg("request_json"),
          "Runs `lenslab analyze` on the scene with the request (JSON: Python's keywords)");
    m.def(
        "analyze_options", [] { return analyze_request_options_json().dump(); },
        "The analysis request's options as JSON (analysis/report/analyze_request_spec.h)");
    py::class_<AnalyzeBatch>(m, "AnalyzeBatch", "A finished lenslab.analyze_many")
        .def_property_readonly("failed", [](const AnalyzeBatch& b) { return b.failed; })
        .def("raise_failure", &raise_failure)
        .def("runs", &batch_runs);
    m.def("analyze_many", &analyze_many, py::arg("json_texts"), py::arg("paths"),
          py::arg("request_json"), py::arg("threads"), py::arg("progress"),
          "analyze on each scene, on `threads` workers (0: all cores), the GIL released");
    m.attr("FIGURES") = bench_figure_names();
}

}  // namespace lenslab::python
