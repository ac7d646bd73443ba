// The library's errors as Python exceptions, with the message the command line prints after
// "lenslab: error: ": a scene's as lenslab.SceneError, a ValueError that also carries the
// JSON path and the reason apart (`path`, `reason`); every other failure a user can act on
// (an unwritable file, too little memory) as lenslab.Error, a RuntimeError.

#include "bindings.h"
#include "util/error.h"
#include "util/scene_error.h"

namespace lenslab::python {

namespace py = pybind11;

void bind_errors(py::module_& m) {
    static py::exception<Error> error(m, "Error", PyExc_RuntimeError);
    static py::exception<SceneError> scene_error(m, "SceneError", PyExc_ValueError);
    // One translator, subclass first: pybind11 tries translators newest first, so two would
    // depend on their order of registration.
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const SceneError& e) {
            // The class called as a class (py::exception's own call operator raises instead).
            py::object instance = py::handle(scene_error.ptr())(e.what());
            instance.attr("path") = e.path();
            instance.attr("reason") = e.reason();
            PyErr_SetObject(scene_error.ptr(), instance.ptr());
        } catch (const Error& e) {
            PyErr_SetString(error.ptr(), e.what());
        }
    });
}

}  // namespace lenslab::python
