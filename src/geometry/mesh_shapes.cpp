#include "geometry/mesh_shapes.h"

#include <cmath>
#include <numbers>

namespace lenslab {

MeshGeometry make_prism(const PrismSpec& spec) {
    const double half_apex = 0.5 * spec.apex_angle_deg * std::numbers::pi / 180.0;
    const double d = spec.side * std::cos(half_apex);
    const double b = spec.side * std::sin(half_apex);
    const Vec3 w = cross(spec.axis, spec.facing);
    const Vec3 apex = spec.center + spec.facing * (0.5 * d);
    const Vec3 left = spec.center - spec.facing * (0.5 * d) - w * b;
    const Vec3 right = spec.center - spec.facing * (0.5 * d) + w * b;
    const Vec3 down = spec.axis * (-0.5 * spec.height), up = spec.axis * (0.5 * spec.height);
    MeshGeometry m;
    // 0-2: the bottom end (apex, left, right), 3-5: the top end.
    m.vertices = {apex + down, left + down, right + down, apex + up, left + up, right + up};
    // (w, axis, facing) is right-handed, so these windings face outward (the tests check it).
    m.triangles = {
        {0, 1, 2}, {3, 5, 4},  // end caps
        {0, 3, 4}, {0, 4, 1},  // refracting face on the -w side
        {0, 2, 5}, {0, 5, 3},  // refracting face on the +w side
        {1, 4, 5}, {1, 5, 2},  // base
    };
    return m;
}

MeshGeometry make_uv_sphere(const Vec3& center, double radius, int slices, int stacks) {
    MeshGeometry m;
    const int rings = stacks - 1;
    m.vertices.reserve(static_cast<size_t>(slices) * rings + 2);
    m.vertices.push_back(center + Vec3{0, radius, 0});  // north pole
    for (int i = 1; i <= rings; ++i) {
        const double theta = std::numbers::pi * i / stacks;
        for (int j = 0; j < slices; ++j) {
            const double phi = 2.0 * std::numbers::pi * j / slices;
            m.vertices.push_back(center + Vec3{std::sin(theta) * std::cos(phi), std::cos(theta),
                                               std::sin(theta) * std::sin(phi)} *
                                              radius);
        }
    }
    const auto south = static_cast<int32_t>(m.vertices.size());
    m.vertices.push_back(center + Vec3{0, -radius, 0});
    auto ring = [&](int i, int j) {
        return static_cast<int32_t>(1 + (i - 1) * slices + j % slices);
    };
    m.triangles.reserve(2 * static_cast<size_t>(slices) * rings);
    for (int j = 0; j < slices; ++j) {
        m.triangles.push_back({0, ring(1, j + 1), ring(1, j)});
        for (int i = 1; i < rings; ++i) {
            m.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i + 1, j)});
            m.triangles.push_back({ring(i, j), ring(i, j + 1), ring(i + 1, j + 1)});
        }
        m.triangles.push_back({ring(rings, j), ring(rings, j + 1), south});
    }
    return m;
}

}  // namespace lenslab
