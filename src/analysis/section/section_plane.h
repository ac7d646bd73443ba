#pragma once
// The plane of a 2-D section view: an origin and two orthonormal in-plane axes. A point of
// the plane has coordinates (a, b) = origin + u a + v b; the section view draws a along the
// picture's width and b up it (DiagramPoint's z and y).

#include "analysis/figures/ray_diagram.h"
#include "math/vec3.h"
#include "scene/scene.h"

namespace lenslab {

struct SectionPlane {
    Vec3 origin;
    Vec3 u{1, 0, 0}, v{0, 1, 0};  // unit and orthogonal

    Vec3 normal() const { return cross(u, v); }
    Vec3 at(double a, double b) const { return origin + u * a + v * b; }
    Vec3 at(const DiagramPoint& p) const { return at(p.z, p.y); }
    // The plane coordinates of a point (its orthogonal projection when off the plane).
    DiagramPoint of(const Vec3& p) const { return {dot(p - origin, u), dot(p - origin, v)}; }
    // Signed distance of a point from the plane, along normal().
    double distance(const Vec3& p) const { return dot(p - origin, normal()); }
};

// The plane a section view shows for `object` (an index into scene.objects, or -1):
// for a lens or a mirror, the plane through its axis containing the camera's up direction, with v
// the up direction and u across it (the lens's axis when the lens lies on its side); for anything
// else, the plane through the object's centre (the scene's centre for -1) facing the camera, v up
// and u to the camera's right.
SectionPlane default_section_plane(const Scene& scene, int object);

// Whether default_section_plane follows `object`'s own axis (a lens's or a mirror's),
// rather than only passing through it.
bool section_plane_follows_axis(const Scene& scene, int object);

// The planes a user can choose: the default above, or a plane of the scene's axes through
// the same point (x-y seen from +z, y-z seen from +x, z-x seen from above, +y).
enum class SectionPlaneChoice { Default, XY, YZ, ZX };
SectionPlane section_plane(const Scene& scene, int object, SectionPlaneChoice choice);

}  // namespace lenslab
