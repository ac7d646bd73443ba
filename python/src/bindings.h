#pragma once
// The parts of the compiled module `lenslab._lenslab`, one concept each; module.cpp adds them.

#include <pybind11/pybind11.h>

namespace lenslab::python {

void bind_errors(pybind11::module_& m);
void bind_scene(pybind11::module_& m);
void bind_render(pybind11::module_& m);
void bind_image(pybind11::module_& m);
void bind_trace(pybind11::module_& m);
void bind_glass(pybind11::module_& m);
void bind_analyze(pybind11::module_& m);
void bind_detect(pybind11::module_& m);
void bind_optimize(pybind11::module_& m);

}  // namespace lenslab::python
