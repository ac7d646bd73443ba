#pragma once
// Is a triangle mesh the boundary of a solid? A mesh is closed when every edge joins exactly
// two triangles that run along it in opposite directions (a consistently oriented 2-manifold
// without boundary); only then do "inside" and "outside" mean something. Its signed volume
// (divergence theorem) then says whether the triangles face out (> 0) or in (< 0).

#include <string>
#include <vector>

#include "geometry/triangle_mesh.h"

namespace lenslab {

struct MeshTopology {
    bool closed = false;
    // When not closed, why, naming the first offending edge in triangle order with the
    // caller's face numbers: "edge (4, 7) belongs to 1 face (face 12)".
    std::string problem;
    // Volume enclosed as the triangles are oriented: negative when they face inward.
    // Meaningful only when closed.
    double signed_volume = 0.0;
    // Two faces that are the same triangle (the same three corner positions, in any order),
    // named with the caller's numbers ("faces 1 and 2 are the same triangle (vertices 1, 2,
    // 3)"); empty when there are none. A ray cannot tell such faces apart, and no bounding
    // volume hierarchy can separate them: a mesh of many makes every ray test all of them.
    std::string duplicate;
};

// `face_of[i]` is the face (polygon) triangle i came from; messages number faces and
// vertices from `index_base` (0 for scene JSON, 1 for OBJ files). Vertices at exactly the
// same position count as one (files often repeat a corner per face).
MeshTopology check_mesh_topology(const std::vector<Vec3>& vertices,
                                 const std::vector<MeshTriangle>& triangles,
                                 const std::vector<int32_t>& face_of, int index_base = 0);

// Reverses the winding of every triangle, turning its normal around.
void flip_triangles(std::vector<MeshTriangle>& triangles);

}  // namespace lenslab
