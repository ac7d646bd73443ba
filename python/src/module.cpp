// `lenslab._lenslab`: the compiled half of the Python package; python/lenslab/__init__.py
// wraps it in the documented API (docs/python.md).

#include "bindings.h"

PYBIND11_MODULE(_lenslab, m) {
    m.doc() = "lenslab's C++ core; use the `lenslab` package, not this module";
    lenslab::python::bind_errors(m);
    lenslab::python::bind_scene(m);
    lenslab::python::bind_render(m);
    lenslab::python::bind_image(m);
    lenslab::python::bind_trace(m);
    lenslab::python::bind_glass(m);
    lenslab::python::bind_analyze(m);
    lenslab::python::bind_detect(m);
    lenslab::python::bind_optimize(m);
}
