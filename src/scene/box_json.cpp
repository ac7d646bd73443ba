#include "scene/box_json.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/mesh_shapes.h"
#include "geometry/mesh_topology.h"
#include "geometry/triangle_mesh.h"
#include "scene/object_spec.h"

namespace lenslab {

namespace {

ElementSpec declare_box() {
    ElementSpec s = shape_spec("box", "a box", false);
    s.params.push_back(point_param("center").describe("centre").in_editor("Centre"));
    s.params.push_back(nested_param(ParamKind::Array, "size")
                           .needed()
                           .as_written("`[x, y, z]`, each `> 0`")
                           .describe("full edge lengths along the box's x, y and z"));
    s.params.push_back(vector_param(ParamKind::Direction, "up", nlohmann::json::array({0, 1, 0}))
                           .describe("where the box's y edges point")
                           .in_editor("Up (y edges)"));
    s.params.push_back(
        vector_param(ParamKind::Direction, "facing", nlohmann::json::array({0, 0, 1}))
            .describe("where its z edges point; perpendicular to up (x = up × facing)")
            .in_editor("Facing (z edges)"));
    s.example = nlohmann::json::parse(
        R"json({"type": "box", "name": "glass block", "center": [0, 0, 0], "size": [0.8, 0.5, 0.3], "material": {"color": 1, "transparency": 1, "ior": 1.5}})json");
    return s;
}

// The corners are centre + (±x, ±y, ±z)/2 along the frame; corner i has bit 0 for +x,
// bit 1 for +y, bit 2 for +z. Each face is two triangles, wound the same way round.
MeshGeometry make_box(const Vec3& centre, const double size[3], const Vec3 axes[3]) {
    MeshGeometry g;
    for (int i = 0; i < 8; ++i) {
        Vec3 v = centre;
        for (int a = 0; a < 3; ++a) v = v + axes[a] * (((i >> a) & 1) ? 0.5 : -0.5) * size[a];
        g.vertices.push_back(v);
    }
    const int faces[6][4] = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1},
                             {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
    for (const auto& f : faces) {
        g.triangles.push_back({f[0], f[1], f[2]});
        g.triangles.push_back({f[0], f[2], f[3]});
    }
    return g;
}

}  // namespace

const ElementSpec& box_spec() {
    static const ElementSpec spec = declare_box();
    return spec;
}

std::shared_ptr<const Shape> read_box(SpecReader& r) {
    const Vec3 centre = r.point("center");
    const nlohmann::json& size = r.require("size");
    const std::string path = r.child_path("size");
    if (!size.is_array() || size.size() != 3)
        throw SceneError(path, "must be [x, y, z] (full edge lengths)");
    double edge[3];
    for (int a = 0; a < 3; ++a) {
        const std::string at = path + "[" + std::to_string(a) + "]";
        edge[a] = JsonObjectReader::as_number(size[a], at);
        if (!(edge[a] > 0)) throw SceneError(at, "must be > 0, got " + format_number(edge[a]));
    }
    const Vec3 up = r.unit_vector("up");
    const Vec3 facing_given = r.unit_vector("facing");
    const double c = dot(up, facing_given);
    if (std::abs(c) > 1e-6) {
        const double degrees = std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / std::numbers::pi;
        if (!r.has("facing")) {
            throw SceneError(
                r.child_path("facing"),
                "the default facing [0, 0, 1] is not perpendicular to up; give facing");
        }
        throw SceneError(r.child_path("facing"),
                         "must be perpendicular to up (the angle between them is " +
                             format_number(std::round(degrees * 1e4) / 1e4) + " degrees)");
    }
    const Vec3 facing = normalize(facing_given - up * c);
    const Vec3 axes[3] = {cross(up, facing), up, facing};
    MeshGeometry g = make_box(centre, edge, axes);
    const std::vector<int32_t> face_of{0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5};
    const MeshTopology topology = check_mesh_topology(g.vertices, g.triangles, face_of);
    // Only sizes at the edge of what doubles resolve (1e-300, or a micron far out) collapse it.
    if (!topology.closed || !(std::abs(topology.signed_volume) > 0)) {
        throw SceneError(
            path, "is too small to build a closed box at this position (its faces collapse)");
    }
    if (topology.signed_volume < 0) flip_triangles(g.triangles);
    return std::make_shared<TriangleMesh>(g.vertices, g.triangles, true);
}

}  // namespace lenslab
