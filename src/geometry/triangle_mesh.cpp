#include "geometry/triangle_mesh.h"

#include <cmath>

namespace lenslab {

namespace {

constexpr int kMaxLeafSize = 4;

// Per-ray set-up of the watertight ray/triangle test (Woop, Benthin & Wald 2013, "Watertight
// Ray/Triangle Intersection", JCGT 2(1)): the ray becomes the +z axis of a sheared frame, so
// the edge functions of two triangles sharing an edge are computed from the same numbers and
// a ray can never slip between them. A closed mesh stays closed for every ray: a ray that
// entered it always finds a way out.
struct ShearedRay {
    int kx, ky, kz;
    double sx, sy, sz;
    Vec3 origin;

    explicit ShearedRay(const Ray& ray) : origin(ray.origin) {
        const Vec3& d = ray.direction;
        const double ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
        kz = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
        kx = (kz + 1) % 3;
        ky = (kx + 1) % 3;
        if (d[kz] < 0) std::swap(kx, ky);  // keep the winding: counter-clockwise stays positive
        sx = d[kx] / d[kz];
        sy = d[ky] / d[kz];
        sz = 1.0 / d[kz];
    }

    // Distance along the ray to the triangle, or NaN when the ray misses it (or it has no
    // area). Both faces count.
    double hit(const std::array<Vec3, 3>& tri) const {
        const Vec3 a = tri[0] - origin, b = tri[1] - origin, c = tri[2] - origin;
        const double ax = a[kx] - sx * a[kz], ay = a[ky] - sy * a[kz];
        const double bx = b[kx] - sx * b[kz], by = b[ky] - sy * b[kz];
        const double cx = c[kx] - sx * c[kz], cy = c[ky] - sy * c[kz];
        double u = cx * by - cy * bx;
        double v = ax * cy - ay * cx;
        double w = bx * ay - by * ax;
        // An edge function that is exactly 0 may be a rounding tie: decide it with more bits.
        if (u == 0.0 || v == 0.0 || w == 0.0) {
            using L = long double;
            u = static_cast<double>(L(cx) * L(by) - L(cy) * L(bx));
            v = static_cast<double>(L(ax) * L(cy) - L(ay) * L(cx));
            w = static_cast<double>(L(bx) * L(ay) - L(by) * L(ax));
        }
        if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0)) return NAN;
        const double det = u + v + w;
        if (det == 0.0) return NAN;
        return (u * sz * a[kz] + v * sz * b[kz] + w * sz * c[kz]) / det;
    }
};

}  // namespace

TriangleMesh::TriangleMesh(const std::vector<Vec3>& vertices,
                           const std::vector<MeshTriangle>& triangles, bool closed,
                           std::string open_reason)
    : m_vertex_count(vertices.size()), m_closed(closed), m_open_reason(std::move(open_reason)) {
    std::vector<Aabb> boxes(triangles.size());
    for (size_t i = 0; i < triangles.size(); ++i) {
        for (int32_t k : triangles[i]) boxes[i].expand(vertices[k]);
        m_bounds.expand(boxes[i]);
    }
    BvhLayout layout = build_bvh(boxes, kMaxLeafSize);
    m_nodes = std::move(layout.nodes);
    // Store the corners in leaf order: a leaf's triangles lie side by side in memory.
    m_triangles.reserve(triangles.size());
    m_normals.reserve(triangles.size());
    for (int index : layout.order) {
        const MeshTriangle& t = triangles[index];
        const std::array<Vec3, 3> corners{vertices[t[0]], vertices[t[1]], vertices[t[2]]};
        const Vec3 n = cross(corners[1] - corners[0], corners[2] - corners[0]);
        const double len = length(n);
        m_triangles.push_back(corners);
        m_normals.push_back(len > 0.0 ? n / len : Vec3{});
    }
}

bool TriangleMesh::intersect(const Ray& ray, double t_min, double t_max, SurfaceHit& hit) const {
    const ShearedRay sheared(ray);
    int best = -1;
    double best_t = t_max;
    traverse_bvh(m_nodes, ray, t_min, t_max, false, [&](int first, int count, double& t_far) {
        bool found = false;
        for (int i = first; i < first + count; ++i) {
            const double t = sheared.hit(m_triangles[i]);
            if (in_range(t, t_min, t_far)) {
                t_far = t;
                best_t = t;
                best = i;
                found = true;
            }
        }
        return found;
    });
    if (best < 0) return false;
    hit.t = best_t;
    hit.point = ray.at(hit.t);
    hit.normal = m_normals[best];
    return true;
}

}  // namespace lenslab
