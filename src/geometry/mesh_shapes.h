#pragma once
// Triangle meshes built from a few numbers: the prism of a spectroscope, and a tessellated
// sphere (tests and benchmarks). Both come out closed with their triangles facing outward.

#include <vector>

#include "geometry/triangle_mesh.h"

namespace lenslab {

struct MeshGeometry {
    std::vector<Vec3> vertices;
    std::vector<MeshTriangle> triangles;
};

// An isosceles triangular prism. Its cross-section (perpendicular to `axis`) is a triangle
// with angle `apex_angle_deg` at the apex between two sides of length `side`; the prism is
// `height` long along `axis`. With w = cross(axis, facing), d = side cos(A/2) (apex to base)
// and b = side sin(A/2) (half the base):
//   apex edge      center + facing d/2             + axis s,  s in [-height/2, height/2]
//   base corners   center - facing d/2  -/+ w b    + axis s
// so `center` is the centre of its bounding box and `facing` points from the base to the
// apex. The faces are the two refracting faces meeting at the apex edge, the base, and two
// end caps. `axis` and `facing` must be unit length and perpendicular.
struct PrismSpec {
    double apex_angle_deg = 60.0;
    double side = 1.0;
    double height = 1.0;
    Vec3 center;
    Vec3 axis{0, 1, 0};
    Vec3 facing{0, 0, 1};
};
MeshGeometry make_prism(const PrismSpec& spec);

// A UV sphere: `stacks` bands from pole to pole (along +y), `slices` around; it has
// 2 slices (stacks - 1) triangles. Its vertices lie on the sphere, so it is slightly smaller.
MeshGeometry make_uv_sphere(const Vec3& center, double radius, int slices, int stacks);

}  // namespace lenslab
