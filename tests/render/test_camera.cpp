// The camera's projection is the inverse of its primary rays: the editor draws its handles
// and light icons where the render shows the points they stand for.

#include <gtest/gtest.h>

#include "render/camera.h"

namespace lenslab {
namespace {

TEST(Camera, ProjectingAPointOnAPrimaryRayGivesItsPixel) {
    CameraSettings s;
    s.position = {1, 2, 3};
    s.direction = normalize(Vec3{-0.3, -0.2, -1});
    s.up = {0, 1, 0};
    s.fov_deg = 35;
    const Camera camera(s, 320, 200);
    for (const auto& [px, py] :
         {std::pair{0.0, 0.0}, {160.0, 100.0}, {17.5, 190.25}, {319.0, 3.0}}) {
        const Ray ray = camera.generate_ray(px, py);
        double x = -1, y = -1;
        ASSERT_TRUE(camera.project(ray.origin + ray.direction * 7.5, x, y));
        EXPECT_NEAR(x, px, 1e-9);
        EXPECT_NEAR(y, py, 1e-9);
    }
    // Behind the eye: nowhere on the film.
    double x = 0, y = 0;
    EXPECT_FALSE(camera.project(s.position - s.direction, x, y));
}

}  // namespace
}  // namespace lenslab
