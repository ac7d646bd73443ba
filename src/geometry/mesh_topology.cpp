#include "geometry/mesh_topology.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numeric>
#include <unordered_map>

namespace lenslab {

namespace {

// For every vertex, the smallest index of a vertex at exactly the same position.
std::vector<int32_t> weld_identical(const std::vector<Vec3>& vertices) {
    std::vector<int32_t> order(vertices.size());
    std::iota(order.begin(), order.end(), 0);
    auto less = [&](int32_t a, int32_t b) {
        const Vec3 &p = vertices[a], &q = vertices[b];
        if (p.x != q.x) return p.x < q.x;
        if (p.y != q.y) return p.y < q.y;
        if (p.z != q.z) return p.z < q.z;
        return a < b;
    };
    std::sort(order.begin(), order.end(), less);
    std::vector<int32_t> canonical(vertices.size());
    for (size_t i = 0; i < order.size(); ++i) {
        const bool same = i > 0 && vertices[order[i]].x == vertices[order[i - 1]].x &&
                          vertices[order[i]].y == vertices[order[i - 1]].y &&
                          vertices[order[i]].z == vertices[order[i - 1]].z;
        canonical[order[i]] = same ? canonical[order[i - 1]] : order[i];
    }
    return canonical;
}

struct EdgeUse {
    int32_t low_to_high = 0;  // triangles running from the lower vertex index to the higher
    int32_t high_to_low = 0;
    int32_t first = -1;  // the first two triangles using the edge
    int32_t second = -1;
};

// The first two triangles with the same corners (after welding), as "faces A and B ...";
// triangles with a repeated corner (no area) are left aside.
std::string find_duplicate(const std::vector<MeshTriangle>& triangles,
                           const std::vector<int32_t>& canonical,
                           const std::function<std::string(int32_t)>& face_name, int index_base) {
    std::vector<std::pair<std::array<int32_t, 3>, int32_t>> keys;
    keys.reserve(triangles.size());
    for (size_t t = 0; t < triangles.size(); ++t) {
        std::array<int32_t, 3> k{canonical[triangles[t][0]], canonical[triangles[t][1]],
                                 canonical[triangles[t][2]]};
        std::sort(k.begin(), k.end());
        if (k[0] != k[1] && k[1] != k[2]) keys.push_back({k, static_cast<int32_t>(t)});
    }
    std::sort(keys.begin(), keys.end());
    for (size_t i = 1; i < keys.size(); ++i) {
        if (keys[i].first != keys[i - 1].first) continue;
        const std::array<int32_t, 3>& v = keys[i].first;
        const auto number = [&](int32_t x) { return std::to_string(int64_t{x} + index_base); };
        return "faces " + face_name(keys[i - 1].second) + " and " + face_name(keys[i].second) +
               " are the same triangle (vertices " + number(v[0]) + ", " + number(v[1]) + ", " +
               number(v[2]) + ")";
    }
    return "";
}

uint64_t edge_key(int32_t a, int32_t b) {
    const auto lo = static_cast<uint32_t>(std::min(a, b)),
               hi = static_cast<uint32_t>(std::max(a, b));
    return (static_cast<uint64_t>(lo) << 32) | hi;
}

}  // namespace

MeshTopology check_mesh_topology(const std::vector<Vec3>& vertices,
                                 const std::vector<MeshTriangle>& triangles,
                                 const std::vector<int32_t>& face_of, int index_base) {
    MeshTopology result;
    auto edge_name = [&](int32_t a, int32_t b) {
        return "edge (" + std::to_string(int64_t{a} + index_base) + ", " +
               std::to_string(int64_t{b} + index_base) + ")";
    };
    auto face_name = [&](int32_t t) { return std::to_string(int64_t{face_of[t]} + index_base); };
    if (triangles.empty()) {
        result.problem = "the mesh has no faces";
        return result;
    }
    const std::vector<int32_t> canonical = weld_identical(vertices);
    result.duplicate = find_duplicate(triangles, canonical, face_name, index_base);
    if (!result.duplicate.empty()) {
        result.problem = result.duplicate;
        return result;
    }
    std::unordered_map<uint64_t, EdgeUse> edges;
    edges.reserve(triangles.size() * 2);
    auto for_each_edge = [&](auto&& fn) {
        for (size_t t = 0; t < triangles.size(); ++t) {
            for (int k = 0; k < 3; ++k) {
                const int32_t a = canonical[triangles[t][k]];
                const int32_t b = canonical[triangles[t][(k + 1) % 3]];
                // A corner repeated (two vertices at one position) makes no edge: the triangle
                // has no area there.
                if (a != b && !fn(static_cast<int32_t>(t), a, b)) return;
            }
        }
    };
    for_each_edge([&](int32_t t, int32_t a, int32_t b) {
        EdgeUse& e = edges[edge_key(a, b)];
        (a < b ? e.low_to_high : e.high_to_low) += 1;
        if (e.first < 0)
            e.first = t;
        else if (e.second < 0)
            e.second = t;
        return true;
    });
    for_each_edge([&](int32_t, int32_t a, int32_t b) {
        const EdgeUse& e = edges[edge_key(a, b)];
        const int32_t uses = e.low_to_high + e.high_to_low;
        if (uses == 2 && e.low_to_high == 1) return true;
        if (uses == 1) {
            result.problem = edge_name(a, b) + " belongs to 1 face (face " + face_name(e.first) +
                             "): the surface has a hole there";
        } else if (uses == 2) {
            result.problem = "faces " + face_name(e.first) + " and " + face_name(e.second) +
                             " both run along " + edge_name(a, b) +
                             " in the same direction: their orientations disagree";
        } else {
            result.problem = edge_name(a, b) + " belongs to " + std::to_string(uses) +
                             " faces (faces " + face_name(e.first) + ", " + face_name(e.second) +
                             ", ...)";
        }
        return false;
    });
    if (!result.problem.empty()) return result;

    // Divergence theorem, about the centre of the bounds to keep the terms small.
    Aabb box;
    for (const Vec3& v : vertices) box.expand(v);
    const Vec3 c = box.centre();
    double six_volume = 0.0;
    for (const MeshTriangle& t : triangles) {
        six_volume += dot(vertices[t[0]] - c, cross(vertices[t[1]] - c, vertices[t[2]] - c));
    }
    result.signed_volume = six_volume / 6.0;
    const Vec3 e = box.extent();
    const double scale = std::max(e.x, std::max(e.y, e.z));
    if (!(std::abs(result.signed_volume) > 1e-12 * scale * scale * scale)) {
        result.problem = "the faces enclose no volume";
        return result;
    }
    result.closed = true;
    return result;
}

void flip_triangles(std::vector<MeshTriangle>& triangles) {
    for (MeshTriangle& t : triangles) std::swap(t[1], t[2]);
}

}  // namespace lenslab
