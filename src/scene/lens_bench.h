#pragma once
// The system data an imported lens file keeps beside its lens: the scene's "bench" block, as
// `lenslab import` writes it (docs/scene-format.md, "Lens file"). The optical bench takes
// its wavelengths, fields, aperture and image plane for what it is not asked otherwise
// (analysis/system/lens_bench_defaults.h); `lenslab export` writes them back.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace lenslab {

struct LensBench {
    std::vector<double> wavelengths;  // nm
    std::optional<double> primary_wavelength;
    // "angle" (degrees), "object_height", "paraxial_image_height", "real_image_height" (mm)
    std::string field_type = "angle";
    std::vector<double> fields_x, fields_y;
    // "entrance_pupil_diameter" (mm), "f_number", "image_na", "object_na", "float_by_stop_size"
    std::string aperture_type;
    double aperture = 0;
    std::optional<double> stop_position;  // from the first vertex
    std::optional<double> stop_semi_diameter;
    std::string ray_aiming;                // "paraxial" or "real" (the file's RAIM); "": not said
    std::optional<double> image_distance;  // last vertex to the image surface
    // The lens_file object (its index in the scene file's "objects") whose file this came
    // from; -1: the scene's own "bench" block, written by `lenslab import`.
    int object = -1;
};

// Reads a "bench" block; throws SceneError at "bench.KEY" for a value of the wrong kind.
LensBench read_lens_bench(const nlohmann::json& bench);

}  // namespace lenslab
