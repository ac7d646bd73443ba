// lenslab.write_image: an array from lenslab.render written by the library's own writer, so
// a file saved from Python is the file `lenslab render -o` writes (PNG sRGB or linear EXR).

#include <pybind11/numpy.h>

#include "bindings.h"
#include "render/image_io.h"

namespace lenslab::python {

namespace {

namespace py = pybind11;

using ImageArray = py::array_t<float, py::array::c_style | py::array::forcecast>;

void write_image_file(const ImageArray& image, const std::string& path, double exposure) {
    if (image.ndim() != 3 || image.shape(2) != 3) {
        throw py::value_error("image: must be an array of shape (height, width, 3)");
    }
    const auto height = static_cast<int>(image.shape(0)), width = static_cast<int>(image.shape(1));
    Film film(width, height);
    const auto pixels = image.unchecked<3>();
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            film.set(x, y, {pixels(y, x, 0), pixels(y, x, 1), pixels(y, x, 2)});
    py::gil_scoped_release unlocked;
    write_image(film, path, exposure);
}

}  // namespace

void bind_image(py::module_& m) {
    m.def("write_image", &write_image_file, py::arg("image"), py::arg("path"),
          py::arg("exposure") = 0.0,
          "Writes an (H, W, 3) linear image as .png (sRGB) or .exr (linear float)");
    m.def("is_supported_image_path", &is_supported_image_path, py::arg("path"));
}

}  // namespace lenslab::python
