#include "scene/lens_bench.h"

#include "scene/json_reader.h"
#include "util/scene_error.h"

namespace lenslab {

namespace {

std::vector<double> bench_numbers(JsonObjectReader& r, const std::string& key) {
    std::vector<double> out;
    const nlohmann::json* v = r.find(key);
    if (!v) return out;
    if (!v->is_array()) throw SceneError(r.child_path(key), "must be a list of numbers");
    for (size_t i = 0; i < v->size(); ++i) {
        out.push_back(JsonObjectReader::as_number(
            (*v)[i], r.child_path(key) + "[" + std::to_string(i) + "]"));
    }
    return out;
}

std::optional<double> bench_number(JsonObjectReader& r, const std::string& key) {
    if (!r.has(key)) return std::nullopt;
    return r.number(key);
}

}  // namespace

LensBench read_lens_bench(const nlohmann::json& bench) {
    JsonObjectReader r(bench, "bench",
                       {"unit", "wavelengths", "primary_wavelength", "field_type", "fields_x",
                        "fields_y", "aperture_type", "aperture", "stop_position",
                        "stop_semi_diameter", "image_distance", "ray_aiming"},
                       "a lens file's bench");
    (void)r.choice("unit", "mm", {"mm"});
    LensBench b;
    b.wavelengths = bench_numbers(r, "wavelengths");
    for (size_t i = 0; i < b.wavelengths.size(); ++i) {
        if (!(b.wavelengths[i] > 0)) {
            throw SceneError("bench.wavelengths[" + std::to_string(i) + "]",
                             "must be a wavelength in nm (> 0)");
        }
    }
    if (r.has("primary_wavelength")) b.primary_wavelength = r.positive("primary_wavelength");
    b.field_type =
        r.choice("field_type", "angle",
                 {"angle", "object_height", "paraxial_image_height", "real_image_height"});
    b.fields_x = bench_numbers(r, "fields_x");
    b.fields_y = bench_numbers(r, "fields_y");
    if (r.has("aperture_type")) {
        b.aperture_type = r.choice(
            "aperture_type", "",
            {"entrance_pupil_diameter", "f_number", "image_na", "object_na", "float_by_stop_size"});
    }
    b.aperture = r.number("aperture", 0.0);
    b.stop_position = bench_number(r, "stop_position");
    b.stop_semi_diameter = bench_number(r, "stop_semi_diameter");
    b.image_distance = bench_number(r, "image_distance");
    if (r.has("ray_aiming")) b.ray_aiming = r.choice("ray_aiming", "", {"paraxial", "real"});
    return b;
}

}  // namespace lenslab
