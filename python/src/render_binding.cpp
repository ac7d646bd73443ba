// lenslab.render's engine: render_scene, as `lenslab render` runs it, as a BackgroundJob
// (background_job.h): progress delivered to Python, Ctrl-C cancelling the render.

#include <pybind11/numpy.h>

#include "background_job.h"
#include "bindings.h"
#include "render/render_session.h"
#include "scene_bridge.h"

namespace lenslab::python {

namespace {

namespace py = pybind11;

// The film as a float32 array of shape (height, width, 3), row 0 at the top as in the files.
py::array_t<float> film_array(const Film& film) {
    static_assert(sizeof(PixelRgb) == 3 * sizeof(float), "PixelRgb must be three packed floats");
    py::array_t<float> image({film.height(), film.width(), 3});
    std::copy_n(reinterpret_cast<const float*>(film.pixels().data()), film.pixels().size() * 3,
                image.mutable_data());
    return image;
}

py::array_t<float> render(const std::string& json_text, const std::string& path, int threads,
                          const py::object& progress) {
    const Scene scene = [&] {
        py::gil_scoped_release unlocked;
        return build_scene(json_text, path);
    }();
    BackgroundJob<RenderResult> job([&scene, threads](RenderControl& control) {
        return render_scene(scene, control, threads);
    });
    const RenderResult result = job.run(progress);  // an exception ends the render
    if (job.control().non_finite_samples() > 0) {
        // The command line's warning, as a Python warning: the image is usable, but say so.
        const std::string text =
            std::to_string(job.control().non_finite_samples()) +
            " samples came out NaN or infinite and were left out of their pixels (a bug in "
            "lenslab; please report it with the scene)";
        if (PyErr_WarnEx(PyExc_RuntimeWarning, text.c_str(), 1) != 0) throw py::error_already_set();
    }
    return film_array(result.film);
}

}  // namespace

void bind_render(py::module_& m) {
    m.def("render", &render, py::arg("json_text"), py::arg("path"), py::arg("threads"),
          py::arg("progress"),
          "Renders the scene; threads <= 0: all cores. Returns linear RGB, float32, (H, W, 3)");
}

}  // namespace lenslab::python
