#include "scene/mesh_json.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <span>
#include <sstream>
#include <tuple>

#include "geometry/mesh_shapes.h"
#include "geometry/mesh_topology.h"
#include "geometry/triangle_mesh.h"
#include "scene/json_reader.h"
#include "scene/limits.h"
#include "scene/obj_reader.h"
#include "scene/object_spec.h"

namespace lenslab {

namespace {

using nlohmann::json;

// Faces as the user numbered them, fan-triangulated, before placement.
struct Polygons {
    MeshGeometry geometry;
    std::vector<int32_t> face_of;  // triangle -> face, for messages
    int index_base = 0;            // 0 for JSON, 1 for OBJ (as the file numbers them)
    std::string key;               // "faces" or "file": where problems with the surface point
};

// Fans a polygon from its first corner: (0, 1, 2), (0, 2, 3), ... Exact for convex polygons,
// and it keeps every polygon edge, so closedness does not depend on the triangulation.
void add_fan(std::span<const int32_t> corners, int32_t face, Polygons& p) {
    for (size_t k = 1; k + 1 < corners.size(); ++k) {
        p.geometry.triangles.push_back({corners[0], corners[k], corners[k + 1]});
        p.face_of.push_back(face);
    }
}

// A point, checked in place; the path is only built for the error message.
Vec3 read_vertex(const json& v, const std::string& base, size_t i) {
    if (v.is_array() && v.size() == 3) {
        Vec3 p;
        bool ok = true;
        for (int k = 0; k < 3; ++k) {
            const json& c = v[k];
            ok = ok && c.is_number();
            if (ok) p[k] = c.get<double>();
            ok = ok && std::abs(p[k]) <= kMaxSceneNumber;
        }
        if (ok) return p;
    }
    return JsonObjectReader::as_vec3(v, element_path(base, i));
}

int32_t read_index(const json& v, const std::string& face_path, size_t k, size_t vertex_count) {
    if (!v.is_number_integer()) {
        const std::string path = element_path(face_path, k);
        const double d = JsonObjectReader::as_number(v, path);
        if (d != std::floor(d)) {
            throw SceneError(path,
                             "must be a whole number (a vertex index), got " + format_number(d));
        }
        if (d >= 0 && d < static_cast<double>(vertex_count)) return static_cast<int32_t>(d);
    } else {
        const int64_t i = v.get<int64_t>();
        if (i >= 0 && static_cast<uint64_t>(i) < vertex_count) return static_cast<int32_t>(i);
    }
    throw SceneError(element_path(face_path, k), "must be a vertex index from 0 to " +
                                                     std::to_string(vertex_count - 1) +
                                                     " (there are " + std::to_string(vertex_count) +
                                                     " vertices), got " + excerpt(v));
}

Polygons read_inline(JsonObjectReader& r) {
    Polygons p;
    p.key = "faces";
    const json& vertices = r.require("vertices");
    const std::string vpath = r.child_path("vertices");
    if (!vertices.is_array() || vertices.size() < 3) {
        throw SceneError(vpath, "must be an array of at least 3 points [[x,y,z], ...]");
    }
    check_count(vertices.size(), kMaxMeshTriangles, vpath, "vertices");
    p.geometry.vertices.reserve(vertices.size());
    for (size_t i = 0; i < vertices.size(); ++i) {
        p.geometry.vertices.push_back(read_vertex(vertices[i], vpath, i));
    }
    const json& faces = r.require("faces");
    const std::string fpath = r.child_path("faces");
    if (!faces.is_array() || faces.empty()) {
        throw SceneError(fpath, "must be an array of faces [[i, j, k], ...] (vertex indices)");
    }
    check_count(faces.size(), kMaxMeshTriangles, fpath, "faces");
    std::vector<int32_t> corners;
    for (size_t f = 0; f < faces.size(); ++f) {
        const json& face = faces[f];
        if (!face.is_array() || face.size() < 3) {
            throw SceneError(
                element_path(fpath, f),
                "a face must be an array of at least 3 vertex indices, got " +
                    (face.is_array() ? std::to_string(face.size()) + " indices" : excerpt(face)));
        }
        corners.clear();
        for (size_t k = 0; k < face.size(); ++k) {
            const int32_t index = read_index(face[k], element_path(fpath, f), k, vertices.size());
            for (int32_t c : corners) {
                if (c == index) {
                    throw SceneError(element_path(fpath, f),
                                     "vertex " + std::to_string(index) + " appears twice");
                }
            }
            corners.push_back(index);
        }
        add_fan(corners, static_cast<int32_t>(f), p);
        check_count(p.geometry.triangles.size(), kMaxMeshTriangles, fpath,
                    "triangles (faces fan-split)");
    }
    return p;
}

Polygons read_obj_file(JsonObjectReader& r, const std::string& base_dir) {
    Polygons p;
    p.key = "file";
    p.index_base = 1;
    const std::string file = r.string("file");
    const std::string path = r.child_path("file");
    namespace fs = std::filesystem;
    const fs::path resolved = fs::path(file).is_absolute() || base_dir.empty()
                                  ? fs::path(file)
                                  : fs::path(base_dir) / file;
    const std::string cannot = "cannot read '" + file + "': ";
    const std::string where =
        resolved.string() == file ? "" : " (looked for " + resolved.string() + ")";
    // Before opening: a device (/dev/zero) would never end, a huge file would fill memory.
    if (auto problem = file_read_problem(resolved.string(), kMaxObjFileBytes)) {
        throw SceneError(path, cannot + *problem + where);
    }
    std::ifstream in(resolved, std::ios::binary);
    if (!in) throw SceneError(path, cannot + std::strerror(errno) + where);
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw SceneError(path, cannot + "read error" + where);

    ObjLimits limits;
    limits.max_coordinate = kMaxSceneNumber;
    limits.max_vertices = kMaxMeshTriangles;
    limits.max_triangles = kMaxMeshTriangles;
    ObjMesh obj;
    // `mtllib` and `usemtl` are ignored: the scene's material applies.
    try {
        obj = read_obj(text.view(), file, limits);
    } catch (const ObjError& e) {
        throw SceneError(path, e.what());  // "FILE:LINE: REASON"
    }
    p.geometry.vertices = std::move(obj.vertices);
    // Every group and object of the file is one surface, faces numbered as in the file.
    for (size_t f = 0; f < obj.faces.size(); ++f) {
        const ObjFace& face = obj.faces[f];
        add_fan(std::span(obj.corners).subspan(face.first, face.count), static_cast<int32_t>(f), p);
    }
    if (p.geometry.triangles.empty()) throw SceneError(path, cannot + "it has no faces (f lines)");
    return p;
}

// Two perpendicular unit vectors from `first_key` and `second_key` (each with a declared
// default). Nearly perpendicular input (within 1e-6 rad) is made exactly perpendicular.
std::pair<Vec3, Vec3> read_frame(SpecReader& r, const std::string& first_key,
                                 const std::string& second_key) {
    const Vec3 first = r.unit_vector(first_key);
    const Vec3 second = r.unit_vector(second_key);
    const double c = dot(first, second);
    if (std::abs(c) > 1e-6) {
        if (!r.has(second_key)) {
            const json& d = r.spec().param(second_key).fallback;
            throw SceneError(
                r.child_path(second_key),
                "the default " + second_key + " [" + format_number(d[0].get<double>()) + ", " +
                    format_number(d[1].get<double>()) + ", " + format_number(d[2].get<double>()) +
                    "] is not perpendicular to " + first_key + "; give " + second_key);
        }
        const double degrees = std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / std::numbers::pi;
        throw SceneError(r.child_path(second_key),
                         "must be perpendicular to " + first_key + " (the angle between them is " +
                             format_number(std::round(degrees * 1e4) / 1e4) + " degrees)");
    }
    return {first, normalize(second - first * c)};
}

// Orients a closed surface outward and builds the shape.
std::shared_ptr<const Shape> build_mesh(JsonObjectReader& r, Polygons p) {
    const std::vector<Vec3>& v = p.geometry.vertices;
    double area = 0.0;
    for (const MeshTriangle& t : p.geometry.triangles) {
        area += length(cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]]));
    }
    if (!(area > 0.0)) throw SceneError(r.child_path(p.key), "every face has zero area");
    const MeshTopology topology =
        check_mesh_topology(v, p.geometry.triangles, p.face_of, p.index_base);
    if (!topology.duplicate.empty()) {
        throw SceneError(r.child_path(p.key), topology.duplicate +
                                                  ": a mesh holds each triangle once (coincident "
                                                  "faces cannot be told apart)");
    }
    // Given inside-out: the divergence theorem counts the volume negative. Turn every face
    // round so the normals point out of the solid, which refraction relies on.
    if (topology.closed && topology.signed_volume < 0) flip_triangles(p.geometry.triangles);
    return std::make_shared<TriangleMesh>(v, p.geometry.triangles, topology.closed,
                                          topology.closed ? "" : topology.problem);
}

}  // namespace

namespace {

ParamSpec direction_or(const std::string& key, const json& fallback, const std::string& doc,
                       const std::string& label) {
    return vector_param(ParamKind::Direction, key, fallback).describe(doc).in_editor(label);
}

ElementSpec declare_mesh() {
    ElementSpec s = shape_spec("mesh", "a mesh", false);
    s.params.push_back(nested_param(ParamKind::Array, "vertices")
                           .as_written("array of points")
                           .describe("inline form: the corners, numbered from 0"));
    s.params.push_back(nested_param(ParamKind::Array, "faces")
                           .as_written("array of faces")
                           .describe("inline form: each face 3 or more vertex numbers"));
    s.params.push_back(nested_param(ParamKind::String, "file")
                           .describe("OBJ form: the OBJ file, relative to the scene's folder"));
    s.params.push_back(number_param("scale", 1)
                           .above(0)
                           .describe("multiplies the model's coordinates")
                           .in_editor("Scale"));
    s.params.push_back(direction_or("up", json::array({0, 1, 0}),
                                    "where the model's +y axis points", "Up (model +y)"));
    s.params.push_back(direction_or("facing", json::array({0, 0, 1}),
                                    "where the model's +z axis points; perpendicular to up",
                                    "Facing (model +z)"));
    s.params.push_back(vector_param(ParamKind::Point, "position", json::array({0, 0, 0}))
                           .describe("where the model's origin goes")
                           .in_editor("Position"));
    s.example = nlohmann::json::parse(
        R"json({"type": "mesh", "name": "tetrahedron", "position": [0, 0, 0], "vertices": [[0, 0.5, 0], [-0.45, -0.25, 0.25], [0.45, -0.25, 0.25], [0, -0.25, -0.5]], "faces": [[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]], "material": {"color": 0.7}})json");
    return s;
}

ElementSpec declare_prism() {
    ElementSpec s = shape_spec("prism", "a prism", false);
    s.params.push_back(number_param("apex_angle", 60)
                           .above(0)
                           .below(180)
                           .in_unit("degrees")
                           .describe("A, the angle between the two refracting faces")
                           .in_editor("Apex angle (degrees)"));
    s.params.push_back(number_param("side", 0)
                           .above(0)
                           .needed()
                           .describe("width of each refracting face, apex edge to base")
                           .in_editor("Face width (side)"));
    s.params.push_back(number_param("height", 0)
                           .above(0)
                           .needed()
                           .describe("length along axis")
                           .in_editor("Height (along axis)"));
    s.params.push_back(point_param("center")
                           .describe("the centre of the prism's bounding box")
                           .in_editor("Centre"));
    s.params.push_back(direction_or("axis", json::array({0, 1, 0}),
                                    "the long axis: the apex edge runs along it",
                                    "Axis (apex edge)"));
    s.params.push_back(direction_or("facing", json::array({0, 0, 1}),
                                    "from the base towards the apex edge; perpendicular to axis",
                                    "Facing (towards apex)"));
    s.example = nlohmann::json::parse(
        R"json({"type": "prism", "name": "prism", "center": [0, 0, 0], "apex_angle": 60, "side": 0.6, "height": 0.6, "material": {"color": 1, "transparency": 1, "ior": 1.5}})json");
    return s;
}

}  // namespace

const ElementSpec& mesh_spec() {
    static const ElementSpec spec = declare_mesh();
    return spec;
}

const ElementSpec& prism_spec() {
    static const ElementSpec spec = declare_prism();
    return spec;
}

std::shared_ptr<const Shape> read_mesh(SpecReader& r, const std::string& base_dir) {
    const bool inline_form = r.has("vertices") || r.has("faces");
    if (inline_form && r.has("file")) {
        throw SceneError(r.child_path("file"),
                         "give either vertices and faces (inline) or file (an OBJ file), not both");
    }
    if (!inline_form && !r.has("file")) {
        throw SceneError(r.path(), "a mesh needs either vertices and faces, or file (an OBJ file)");
    }
    Polygons p = inline_form ? read_inline(r) : read_obj_file(r, base_dir);

    const double scale = r.real("scale");
    const Vec3 position = r.point("position");
    const auto [up, facing] = read_frame(r, "up", "facing");
    const Vec3 right = cross(up, facing);  // where the model's +x goes: a rotation, no mirror
    for (Vec3& v : p.geometry.vertices) {
        v = position + (right * v.x + up * v.y + facing * v.z) * scale;
    }
    return build_mesh(r, std::move(p));
}

std::shared_ptr<const Shape> read_prism(SpecReader& r) {
    PrismSpec spec;
    spec.apex_angle_deg = r.real("apex_angle");
    spec.side = r.real("side");
    spec.height = r.real("height");
    spec.center = r.point("center");
    std::tie(spec.axis, spec.facing) = read_frame(r, "axis", "facing");
    MeshGeometry g = make_prism(spec);
    Polygons p;
    p.key = "side";
    p.face_of = {0, 1, 2, 2, 3, 3, 4, 4};
    p.geometry = std::move(g);
    auto shape = build_mesh(r, std::move(p));
    // Built closed by construction; only sizes at the edge of what doubles resolve (a height
    // of 1e-307, or a millimetre far from the origin) collapse faces and open it.
    if (!static_cast<const TriangleMesh&>(*shape).is_closed()) {
        throw SceneError(
            r.path(),
            "side " + format_number(spec.side) + " and height " + format_number(spec.height) +
                " are too small to build a closed prism at this position (its faces collapse)");
    }
    return shape;
}

void check_mesh_material(JsonObjectReader& r, const Shape& shape, const Material& material) {
    if (shape.is_closed() || material.transparency == 0.0) return;
    throw SceneError(r.child_path(r.has("file") ? "file" : "faces"),
                     "the mesh is not closed: " + shape.open_reason() +
                         "; only a closed mesh can be transparent (an open one would be a set "
                         "of thin panes, not a solid): close it, or give it an opaque material "
                         "(transparency 0)");
}

}  // namespace lenslab
