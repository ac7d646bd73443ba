// lenslab.detect's engine: run_detection (analysis/detectors/detection_run.h), the work of `lenslab
// detect`, as a BackgroundJob (Ctrl-C cancels it), kept as a DetectionRun whose maps come out
// as numpy arrays and whose files are the command line's.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <filesystem>

#include "analysis/detectors/detection_run.h"
#include "analysis/detectors/detector_files.h"
#include "background_job.h"
#include "bindings.h"
#include "scene_bridge.h"
#include "util/output_path.h"

namespace lenslab::python {

namespace {

namespace py = pybind11;

using Map = py::array_t<double>;

// A finished detection: the measurements, the settings they were made with and the scene's name.
struct DetectionRun {
    std::string name;
    DetectionSettings settings;
    DetectionResult result;

    const DetectorMeasurement& detector(int i) const {
        if (i < 0 || i >= static_cast<int>(result.detectors.size()))
            throw py::index_error("detector " + std::to_string(i));
        return result.detectors[static_cast<size_t>(i)];
    }
};

// Cell values (cell index = iv * cells_u + iu, from the lowest v) as `count` maps of shape
// (cells_v, cells_u), row 0 the highest v as in the EXR and PNG: what imshow shows upright.
template <class Value>
Map cell_maps(const DetectorGrid& g, int count, const Value& value) {
    const py::ssize_t nu = g.cells_u(), nv = g.cells_v();
    Map maps({static_cast<py::ssize_t>(count), nv, nu});
    auto out = maps.mutable_unchecked<3>();
    for (int k = 0; k < count; ++k)
        for (int c = 0; c < g.cell_count(); ++c) out(k, nv - 1 - c / nu, c % nu) = value(k, c);
    return maps;
}

Map irradiance_map(const DetectionRun& run, int i) {
    const DetectorMeasurement& m = run.detector(i);
    Map maps = cell_maps(m.grid, 1, [&m](int, int c) { return m.irradiance(c); });
    return maps.reshape({m.grid.cells_v(), m.grid.cells_u()});
}

Map band_maps(const DetectionRun& run, int i) {
    const DetectorMeasurement& m = run.detector(i);
    return cell_maps(m.grid, m.bands(), [&m](int b, int c) { return m.band_irradiance(b, c); });
}

Map area_map(const DetectionRun& run, int i) {
    const DetectorMeasurement& m = run.detector(i);
    Map maps = cell_maps(m.grid, 1, [&m](int, int c) { return m.grid.cell_area(c); });
    return maps.reshape({m.grid.cells_v(), m.grid.cells_u()});
}

py::tuple vec(const Vec3& v) { return py::make_tuple(v.x, v.y, v.z); }

// {"extent": (u_min, u_max, v_min, v_max), "origin", "u_axis", "v_axis", "band_edges"}
py::dict geometry(const DetectionRun& run, int i) {
    const DetectorMeasurement& m = run.detector(i);
    const DetectorGrid& g = m.grid;
    py::dict d;
    d["extent"] = py::make_tuple(g.u_min(), g.u_max(), g.v_min(), g.v_max());
    d["origin"] = vec(g.frame().origin);
    d["u_axis"] = vec(g.frame().u);
    d["v_axis"] = vec(g.frame().v);
    d["band_edges"] = m.settings.band_edges;
    return d;
}

// Writes <stem>.csv, .exr and .png per detector into `folder`, as `lenslab detect -o` does;
// the files' paths, per detector.
std::vector<std::vector<std::string>> save(const DetectionRun& run, const std::string& folder,
                                           bool log) {
    py::gil_scoped_release unlocked;
    const std::vector<std::string> stems = detector_file_stems(run.result);
    check_output_directory(folder);
    if (std::filesystem::is_directory(folder)) {
        for (const std::string& stem : stems)
            for (const std::string& file : detector_file_paths(folder, stem))
                check_output_file(file);
    }
    create_output_directory(folder);
    std::vector<std::vector<std::string>> files;
    for (size_t i = 0; i < run.result.detectors.size(); ++i) {
        write_detector_files(run.result.detectors[i], run.settings, folder, stems[i],
                             log ? ColourScale::Log : ColourScale::Linear);
        files.push_back(detector_file_paths(folder, stems[i]));
    }
    return files;
}

DetectionRun detect(const std::string& json_text, const std::string& path, int threads,
                    const py::object& progress) {
    DetectionRun run;
    run.name = path.empty() ? "scene" : path;
    const Scene scene = [&] {
        py::gil_scoped_release unlocked;
        Scene built = build_scene(json_text, path);
        check_detectable(built, run.name);
        return built;
    }();
    run.settings = detection_settings(scene, threads);
    BackgroundJob<DetectionResult> job([&scene, &run](RenderControl& control) {
        return measure_detectors(scene, run.settings, control);
    });
    run.result = job.run(progress);
    return run;
}

}  // namespace

void bind_detect(py::module_& m) {
    py::class_<DetectionRun>(m, "DetectionRun", "A finished lenslab.detect (use lenslab.Detection)")
        .def_property_readonly("count",
                               [](const DetectionRun& r) { return r.result.detectors.size(); })
        .def("summary_json",
             [](const DetectionRun& r) {
                 return detection_json(r.name, r.settings, r.result).dump();
             })
        .def("irradiance", &irradiance_map, py::arg("detector"))
        .def("band_irradiance", &band_maps, py::arg("detector"))
        .def("cell_area", &area_map, py::arg("detector"))
        .def("geometry", &geometry, py::arg("detector"))
        .def("save", &save, py::arg("folder"), py::arg("log"));
    m.def("detect", &detect, py::arg("json_text"), py::arg("path"), py::arg("threads"),
          py::arg("progress"),
          "Measures the scene's detectors as `lenslab detect` does; threads <= 0: all cores");
}

}  // namespace lenslab::python
