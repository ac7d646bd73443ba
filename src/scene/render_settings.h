#pragma once

#include <cstdint>
#include <string>

#include "optics/rgb.h"

namespace lenslab {

// The scene file's `render` block; the command line may override any of it.
struct RenderSettings {
    int width = 640;
    int height = 480;
    int spp = 4;            // camera samples per pixel
    int max_depth = 8;      // longest chain of specular bounces followed
    uint64_t seed = 1;
    Rgb ambient{0, 0, 0};   // ambient radiance Ia lighting every diffuse surface
    Rgb background{0, 0, 0};  // radiance of rays that leave the scene
    int light_samples = 1;  // shadow rays per area light per camera sample
    double min_weight = 1e-4;  // specular branches carrying less are not followed
    std::string integrator = "whitted";
};

}  // namespace lenslab
