// lenslab.write_image: an array from lenslab.render written by the library's own writer, so
// a file saved from Python is the file `lenslab render -o` writes (PNG sRGB or linear EXR);
// lenslab.colour_speckle: the colour-speckle index of a PNG or an 8-bit picture.

#include <pybind11/numpy.h>

#include "bindings.h"
#include "image/colour_speckle.h"
#include "image/image_io.h"
#include "scene/render_settings_spec.h"
#include "scene/render_tone_map.h"

namespace lenslab::python {

namespace {

namespace py = pybind11;

using ImageArray = py::array_t<float, py::array::c_style | py::array::forcecast>;

void write_image_file(const ImageArray& image, const std::string& path, double exposure,
                      const std::string& tone_map, double highlight_stops) {
    RenderSettings settings;
    settings.highlight_stops = highlight_stops;
    // Checked against the render block's declarations, as a scene file's would be.
    const ElementSpec& spec = render_settings_spec();
    if (auto problem = choice_problem(spec.param("tone_map"), tone_map))
        throw py::value_error("tone_map: " + *problem);
    settings.tone_map = choice_named<ToneMapCurve>(kToneMapNames, tone_map);
    if (auto problem = range_problem(spec.param("highlight_stops"), highlight_stops))
        throw py::value_error("highlight_stops: " + *problem);
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
    write_image(film, path, tone_map_for(settings, exposure));
}

using Rgb8Array = py::array_t<uint8_t, py::array::c_style | py::array::forcecast>;

double speckle_of_rgb8(const Rgb8Array& rgb, double cx, double cy, double radius) {
    if (rgb.ndim() != 3 || rgb.shape(2) != 3) {
        throw py::value_error("picture: must be an array of shape (height, width, 3)");
    }
    Image8 image{static_cast<int>(rgb.shape(1)), static_cast<int>(rgb.shape(0)), {}};
    image.rgb.assign(rgb.data(), rgb.data() + rgb.size());
    return colour_speckle(image, {cx, cy, radius});
}

double speckle_of_png(const std::string& path, double cx, double cy, double radius) {
    return colour_speckle(read_png(path), {cx, cy, radius});
}

}  // namespace

void bind_image(py::module_& m) {
    m.def("colour_speckle_rgb8", &speckle_of_rgb8, py::arg("rgb"), py::arg("cx"), py::arg("cy"),
          py::arg("radius"));
    m.def("colour_speckle_png", &speckle_of_png, py::arg("path"), py::arg("cx"), py::arg("cy"),
          py::arg("radius"));
    m.def("write_image", &write_image_file, py::arg("image"), py::arg("path"),
          py::arg("exposure") = 0.0, py::arg("tone_map") = "clip", py::arg("highlight_stops") = 8.0,
          "Writes an (H, W, 3) linear image as .png (sRGB through the tone map) or .exr (linear "
          "float)");
    m.def("is_supported_image_path", &is_supported_image_path, py::arg("path"));
}

}  // namespace lenslab::python
