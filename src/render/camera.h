#pragma once

#include "math/ray.h"
#include "scene/camera_settings.h"

namespace lenslab {

// Pinhole camera: maps film coordinates (pixels, y down) to primary rays.
class Camera {
public:
    Camera(const CameraSettings& s, int width, int height);
    // (px, py) in pixel units: (0, 0) is the top-left corner of the image.
    Ray generate_ray(double px, double py) const;
    // The inverse: where `p` appears on the film (pixel units), or false when it is not in
    // front of the camera. The editor draws handles and light icons with it.
    bool project(const Vec3& p, double& px, double& py) const;

private:
    Vec3 m_origin, m_forward, m_right, m_up;
    double m_half_height = 1, m_half_width = 1;
    int m_width, m_height;
};

}  // namespace lenslab
