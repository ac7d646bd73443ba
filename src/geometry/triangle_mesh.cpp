#include "geometry/triangle_mesh.h"

#include <cmath>
#include <limits>

#include "accel/bvh_build.h"

namespace lenslab {

namespace {

constexpr int kTrianglesPerLeaf = 4;

float round_down(double v) {
    const auto f = static_cast<float>(v);
    return static_cast<double>(f) <= v ? f
                                       : std::nextafter(f, -std::numeric_limits<float>::infinity());
}
float round_up(double v) {
    const auto f = static_cast<float>(v);
    return static_cast<double>(f) >= v ? f
                                       : std::nextafter(f, std::numeric_limits<float>::infinity());
}

// The slab test of Aabb::hit with its conservative far distance (Ize 2013), on a float box,
// with the near and far planes chosen by the ray's direction signs instead of swapped.
struct BoxRay {
    Vec3 origin, inv;
    int neg[3];

    explicit BoxRay(const Ray& ray)
        : origin(ray.origin),
          inv{1.0 / ray.direction.x, 1.0 / ray.direction.y, 1.0 / ray.direction.z},
          // From 1 / d, not d: a direction component of -0 gives -inf, a far side first.
          neg{inv.x < 0, inv.y < 0, inv.z < 0} {}

    bool hit(const float* lo, const float* hi, double t_min, double t_max) const {
        constexpr double kEps = std::numeric_limits<double>::epsilon() * 0.5;
        constexpr double kFarScale = 1.0 + 2.0 * (3.0 * kEps / (1.0 - 3.0 * kEps));
        for (int a = 0; a < 3; ++a) {
            const double near = neg[a] ? hi[a] : lo[a];
            const double far = neg[a] ? lo[a] : hi[a];
            const double t0 = (near - origin[a]) * inv[a];
            const double t1 = (far - origin[a]) * inv[a] * kFarScale;
            // NaN (0 * inf) comparisons fail, which keeps the interval: conservative.
            t_min = t0 > t_min ? t0 : t_min;
            t_max = t1 < t_max ? t1 : t_max;
        }
        return t_min <= t_max;
    }
};

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
    const BvhLayout layout = build_bvh(boxes, kTrianglesPerLeaf);
    m_nodes.reserve(layout.nodes.size());
    for (const BvhNode& n : layout.nodes) {
        Node c{};
        for (int a = 0; a < 3; ++a) {
            c.lo[a] = round_down(n.box.lo[a]);
            c.hi[a] = round_up(n.box.hi[a]);
        }
        c.first = n.first;
        c.count_axis = n.count > 0 ? n.count << 2 : n.axis;
        m_nodes.push_back(c);
    }
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
    if (m_nodes.empty()) return false;
    const ShearedRay sheared(ray);
    const BoxRay box_ray(ray);
    int best = -1;
    int stack[kBvhStackSize];  // the builder's depth bound holds here too
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const int index = stack[--top];
        const Node& node = m_nodes[index];
        if (!box_ray.hit(node.lo, node.hi, t_min, t_max)) continue;
        const int count = node.count_axis >> 2;
        if (count > 0) {
            for (int i = node.first; i < node.first + count; ++i) {
                const double t = sheared.hit(m_triangles[i]);
                if (in_range(t, t_min, t_max)) {
                    t_max = t;
                    best = i;
                }
            }
            continue;
        }
        // The left child holds the lower coordinates along the split axis: visit the nearer
        // child first so its hits shrink t_max before the farther one is tested.
        const int left = index + 1, right = node.first;
        if (box_ray.neg[node.count_axis]) {
            stack[top++] = left;
            stack[top++] = right;
        } else {
            stack[top++] = right;
            stack[top++] = left;
        }
    }
    if (best < 0) return false;
    hit.t = t_max;
    hit.point = ray.at(hit.t);
    hit.normal = m_normals[best];
    return true;
}

}  // namespace lenslab
