#pragma once
// A surface made of triangles that share vertices, with its own BVH over the triangles so a
// ray costs O(log n) triangle tests. A closed, consistently oriented mesh (see
// mesh_topology.h) is a solid: its normals point out of it and refraction enters and leaves
// it like a sphere. An open mesh is a set of two-sided triangles.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/shape.h"

namespace lenslab {

using MeshTriangle = std::array<int32_t, 3>;  // vertex indices, counter-clockwise seen from outside

class TriangleMesh final : public Shape {
public:
    // `closed` says the caller checked (check_mesh_topology) that every edge joins exactly two
    // triangles running along it in opposite directions, and oriented the triangles outward;
    // otherwise `open_reason` says why it is not closed. Triangles of zero area are never hit.
    TriangleMesh(const std::vector<Vec3>& vertices, const std::vector<MeshTriangle>& triangles,
                 bool closed, std::string open_reason = {});

    bool intersect(const Ray& ray, double t_min, double t_max, SurfaceHit& hit) const override;
    Aabb bounds() const override { return m_bounds; }
    bool is_closed() const override { return m_closed; }
    // Why the mesh is not closed ("edge (4, 7) belongs to 1 face ..."); empty when it is.
    std::string open_reason() const override { return m_open_reason; }
    void for_each_facet(const FacetVisitor& visit) const override {
        for (const std::array<Vec3, 3>& t : m_triangles) visit(t.data(), 3);
    }

    size_t triangle_count() const { return m_triangles.size(); }
    size_t vertex_count() const { return m_vertex_count; }
    // Triangle i in BVH order (not the input order): its corners and unit normal (zero for a
    // degenerate triangle).
    const std::array<Vec3, 3>& triangle(size_t i) const { return m_triangles[i]; }
    const Vec3& normal(size_t i) const { return m_normals[i]; }

private:
    std::vector<std::array<Vec3, 3>> m_triangles;  // corners, in BVH leaf order
    std::vector<Vec3> m_normals;                   // unit face normals, same order
    // BVH node, 32 bytes (two per cache line): a 100k-triangle mesh's traversal is bound by
    // memory, so the box is stored in float, rounded outward so it still holds its triangles.
    struct Node {
        float lo[3], hi[3];
        int32_t first;       // leaf: first triangle; inner: index of the right child (left is next)
        int32_t count_axis;  // leaf: triangle count << 2; inner: split axis (count 0)
    };
    std::vector<Node> m_nodes;
    Aabb m_bounds;
    size_t m_vertex_count = 0;
    bool m_closed = false;
    std::string m_open_reason;
};

}  // namespace lenslab
