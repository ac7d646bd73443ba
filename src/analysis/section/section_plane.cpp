#include "analysis/section/section_plane.h"

#include <cmath>

namespace lenslab {

namespace {

// The camera's right and up, with a fallback when the file's up is parallel to the view.
void section_camera_right_up(const CameraSettings& camera, Vec3& right, Vec3& up) {
    up = normalize(camera.up);
    right = cross(camera.direction, up);
    if (length(right) < 1e-9) right = cross(camera.direction, Vec3{0, 0, 1});
    if (length(right) < 1e-9) right = Vec3{1, 0, 0};
    right = normalize(right);
}

}  // namespace

SectionPlane default_section_plane(const Scene& scene, int object) {
    Vec3 right, up;
    section_camera_right_up(scene.camera, right, up);
    SectionPlane plane;
    plane.origin = scene.objects.empty() ? Vec3{} : scene.bounds().centre();
    plane.u = normalize(right - up * dot(right, up));
    plane.v = normalize(cross(cross(right, up), plane.u));  // up, made orthogonal to u
    if (object < 0 || object >= int(scene.objects.size())) return plane;
    const Shape& shape = *scene.objects[object].shape;
    plane.origin = shape.bounding_sphere().centre;
    const std::optional<OpticalAxis> optical = shape.optical_axis();
    if (!optical) return plane;
    const Vec3 axis = optical->direction;
    plane.origin = optical->centre;
    const Vec3 n = cross(axis, up);
    if (length(n) < 1e-9) {  // the axis is vertical: any vertical plane holds it
        plane.v = up;
        plane.u = normalize(right - up * dot(right, up));
        return plane;
    }
    plane.v = up;
    plane.u = normalize(cross(up, normalize(n)));
    if (dot(plane.u, right) < 0) plane.u = -plane.u;  // not mirrored against the 3-D view
    return plane;
}

bool section_plane_follows_axis(const Scene& scene, int object) {
    return object >= 0 && object < int(scene.objects.size()) &&
           scene.objects[size_t(object)].shape->optical_axis().has_value();
}

SectionPlane section_plane(const Scene& scene, int object, SectionPlaneChoice choice) {
    SectionPlane plane = default_section_plane(scene, object);
    switch (choice) {
        case SectionPlaneChoice::Default:
            break;
        case SectionPlaneChoice::XY:
            plane.u = {1, 0, 0}, plane.v = {0, 1, 0};
            break;
        case SectionPlaneChoice::YZ:
            plane.u = {0, 0, -1}, plane.v = {0, 1, 0};
            break;
        case SectionPlaneChoice::ZX:
            plane.u = {1, 0, 0}, plane.v = {0, 0, -1};
            break;
    }
    return plane;
}

}  // namespace lenslab
