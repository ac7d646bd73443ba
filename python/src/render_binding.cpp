// lenslab.render's engine: render_scene, as `lenslab render` runs it, on a thread of its own
// while the calling thread, the GIL released between polls, delivers progress to Python and
// watches for Ctrl-C. Both stop the render through its RenderControl, and the Python
// exception (KeyboardInterrupt, or whatever the progress callback raised) goes up.

#include <pybind11/numpy.h>

#include <atomic>
#include <chrono>
#include <future>

#include "bindings.h"
#include "render/render_session.h"
#include "scene_bridge.h"

namespace lenslab::python {

namespace {

namespace py = pybind11;

// How often the calling thread looks at the render: Ctrl-C answers within about this.
constexpr auto kPollInterval = std::chrono::milliseconds(20);

// The film as a float32 array of shape (height, width, 3), row 0 at the top as in the files.
py::array_t<float> film_array(const Film& film) {
    static_assert(sizeof(PixelRgb) == 3 * sizeof(float), "PixelRgb must be three packed floats");
    py::array_t<float> image({film.height(), film.width(), 3});
    std::copy_n(reinterpret_cast<const float*>(film.pixels().data()), film.pixels().size() * 3,
                image.mutable_data());
    return image;
}

// A render running on its own thread. Destroying it while the render runs (an exception in
// the caller) cancels the render and waits for it, so it never outlives what it reads.
class BackgroundRender {
public:
    BackgroundRender(Scene scene, int threads)
        : m_scene(std::move(scene)),
          m_control([this](double fraction) { m_progress.store(fraction); }) {
        m_result = std::async(std::launch::async, [this, threads] {
            return render_scene(m_scene, m_control, threads);
        });
    }
    ~BackgroundRender() {
        if (!m_result.valid()) return;
        m_control.cancel();
        py::gil_scoped_release unlocked;
        m_result.wait();
    }
    BackgroundRender(const BackgroundRender&) = delete;
    BackgroundRender& operator=(const BackgroundRender&) = delete;

    // Waits up to `interval` with the GIL released; true when the render has finished.
    bool wait(std::chrono::milliseconds interval) {
        py::gil_scoped_release unlocked;
        return m_result.wait_for(interval) == std::future_status::ready;
    }
    double progress() const { return m_progress.load(); }
    int64_t non_finite_samples() const { return m_control.non_finite_samples(); }
    RenderResult result() { return m_result.get(); }  // rethrows the render's exception

private:
    Scene m_scene;
    std::atomic<double> m_progress{-1.0};
    RenderControl m_control;
    std::future<RenderResult> m_result;
};

py::array_t<float> render(const std::string& json_text, const std::string& path, int threads,
                          const py::object& progress) {
    Scene scene = [&] {
        py::gil_scoped_release unlocked;
        return build_scene(json_text, path);
    }();
    BackgroundRender job(std::move(scene), threads);
    double reported = -1.0;
    const auto report_progress = [&] {
        const double fraction = job.progress();
        if (progress.is_none() || fraction == reported) return;
        reported = fraction;
        progress(fraction);  // an exception it raises ends the render (~BackgroundRender)
    };
    for (bool done = false; !done;) {
        done = job.wait(kPollInterval);
        report_progress();
        // Runs Python's SIGINT handler on the main thread: KeyboardInterrupt on Ctrl-C.
        if (!done && PyErr_CheckSignals() != 0) throw py::error_already_set();
    }
    const RenderResult result = job.result();
    if (job.non_finite_samples() > 0) {
        // The command line's warning, as a Python warning: the image is usable, but say so.
        const std::string text =
            std::to_string(job.non_finite_samples()) +
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
