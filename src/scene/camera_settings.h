#pragma once

#include "math/vec3.h"

namespace lenslab {

// A pinhole camera as the scene file gives it.
struct CameraSettings {
    Vec3 position{0, 0, 5};
    Vec3 direction{0, 0, -1};  // unit; from `look_at - position` or given directly
    Vec3 up{0, 1, 0};
    double fov_deg = 40.0;  // vertical field of view
};

}  // namespace lenslab
