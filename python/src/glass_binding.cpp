// lenslab.glass(name): a glass of the catalogues `lenslab glass` reads, found by the same
// lookup, whose n() takes a wavelength or an array of them.

#include <pybind11/numpy.h>

#include <sstream>

#include "bindings.h"
#include "optics/glass_library.h"

namespace lenslab::python {

namespace {

namespace py = pybind11;

using Wavelengths = py::array_t<double, py::array::c_style | py::array::forcecast>;

const Glass& glass_named(const std::string& name) {
    const GlassLookup found = lookup_glass(name);
    if (!found.glass) throw py::value_error(found.error);
    return *found.glass;
}

// Refuses, as `lenslab glass NAME --wavelength` does, a wavelength the data does not cover.
void check_range(const Glass& g, double nm) {
    const IndexModel& m = *g.model;
    if (nm >= m.min_nm && nm <= m.max_nm) return;
    std::ostringstream text;
    text << "wavelength " << nm << " nm is outside " << g.name << "'s validity range " << m.min_nm
         << "-" << m.max_nm << " nm (" << g.source << ")";
    throw py::value_error(text.str());
}

// The index at each wavelength (nm, in air): a float for a number, else an array of its shape.
py::object index_at(const Glass& g, const Wavelengths& nm) {
    const double* in = nm.data();
    for (py::ssize_t i = 0; i < nm.size(); ++i) check_range(g, in[i]);
    if (nm.ndim() == 0) return py::float_(g.model->n(in[0]));
    Wavelengths n(std::vector<py::ssize_t>(nm.shape(), nm.shape() + nm.ndim()));
    double* out = n.mutable_data();
    {
        py::gil_scoped_release unlocked;  // a long array takes a while
        for (py::ssize_t i = 0; i < nm.size(); ++i) out[i] = g.model->n(in[i]);
    }
    return n;
}

}  // namespace

void bind_glass(py::module_& m) {
    py::class_<Glass>(m, "Glass", "A glass of lenslab's catalogues (lenslab.glass(name))")
        .def_readonly("name", &Glass::name)
        .def_property_readonly("maker",
                               [](const Glass& g) { return g.maker.empty() ? "builtin" : g.maker; })
        .def_readonly("description", &Glass::description)
        .def_readonly("source", &Glass::source)
        .def_property_readonly("n_d", [](const Glass& g) { return g.model->n_d(); })
        .def_property_readonly("V_d", [](const Glass& g) { return g.model->abbe_number(); })
        .def_property_readonly("min_nm", [](const Glass& g) { return g.model->min_nm; })
        .def_property_readonly("max_nm", [](const Glass& g) { return g.model->max_nm; })
        .def("n", &index_at, py::arg("wavelengths_nm"),
             "Refractive index at wavelengths in air in nm: a number or an array of them")
        .def("__repr__", [](const Glass& g) { return "<lenslab.Glass " + glass_label(g) + ">"; });
    // The catalogues live as long as the process: Python refers to their glasses.
    m.def("glass", &glass_named, py::arg("name"), py::return_value_policy::reference,
          "The glass `name` (N-BK7, MAKER:NAME, ...), looked up as `lenslab glass NAME` does");
}

}  // namespace lenslab::python
