// Scenes from Python: the checks behind lenslab.Scene (python/lenslab/_scene.py).

#include "scene_bridge.h"

#include <pybind11/stl.h>

#include "bindings.h"
#include "optics/spectral_table.h"
#include "scene/json_reader.h"
#include "scene/type_listing.h"

namespace lenslab::python {

namespace py = pybind11;

Scene build_scene(const std::string& json_text, const std::string& path,
                  const SceneReadOptions& options) {
    const nlohmann::json root = parse_json_strict(json_text, path.empty() ? "scene" : path);
    return path.empty() ? scene_from_json(root, "", options)
                        : scene_from_file_json(root, path, options);
}

void bind_scene(py::module_& m) {
    m.def(
        "check_scene_file",
        [](const std::string& path) {
            py::gil_scoped_release unlocked;
            (void)read_scene_json_file(path);
        },
        py::arg("path"), "Refuses a scene file that cannot be read or is not JSON (SceneError)");
    m.def(
        "check_scene",
        [](const std::string& json_text, const std::string& path, bool require_camera) {
            py::gil_scoped_release unlocked;
            (void)build_scene(json_text, path, {.require_camera = require_camera});
        },
        py::arg("json_text"), py::arg("path"), py::arg("require_camera"),
        "Builds the scene and throws it away: SceneError if it is not a valid scene");
    m.def("default_scene_text", &default_scene_text, "The built-in default scene's JSON");
    m.def(
        "spectral_data_json",
        [](const std::vector<double>& nm, double blackbody, const std::vector<double>& rgb) {
            // std::invalid_argument (a value out of range) reaches Python as ValueError.
            if (!rgb.empty() && rgb.size() != 3)
                throw std::invalid_argument("rgb: give three channels (R, G, B)");
            const std::optional<Rgb> light =
                rgb.empty() ? std::nullopt : std::optional<Rgb>(Rgb{rgb[0], rgb[1], rgb[2]});
            return spectral_columns(spectral_rows(nm, blackbody, light), blackbody != 0,
                                    light.has_value())
                .dump();
        },
        py::arg("nm"), py::arg("blackbody"), py::arg("rgb"),
        "The columns of `lenslab spectra --json` (rgb: empty or three channels)");
    m.def(
        "types_json", [] { return scene_types_json().dump(); },
        "The object and light types and their keys, as `lenslab types --json`");
}

}  // namespace lenslab::python
