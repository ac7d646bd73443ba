// Mesh and prism objects in scene files: inline faces, OBJ files next to the scene, placement,
// the inside-out fix, and which open meshes are accepted.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "analysis/trace/ray_tree.h"
#include "geometry/triangle_mesh.h"
#include "scene/json_reader.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

namespace fs = std::filesystem;

const std::string kDataDir = std::string(LENSLAB_TEST_DATA) + "/scene/data";

std::string mesh_scene_with(const std::string& object) {
    return R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]}, "objects": [)" + object +
           "]}";
}

// The unit cube [0, 1]^3 with quad faces, each counter-clockwise seen from outside.
const char* kCubeVertices =
    R"("vertices": [[0,0,0], [1,0,0], [1,1,0], [0,1,0], [0,0,1], [1,0,1], [1,1,1], [0,1,1]])";
const char* kCubeFaces =
    R"("faces": [[0,3,2,1], [4,5,6,7], [0,1,5,4], [2,3,7,6], [0,4,7,3], [1,2,6,5]])";
const char* kCubeFacesInsideOut =
    R"("faces": [[1,2,3,0], [7,6,5,4], [4,5,1,0], [6,7,3,2], [3,7,4,0], [5,6,2,1]])";

const TriangleMesh& mesh_of(const Scene& s, int i) {
    return dynamic_cast<const TriangleMesh&>(*s.objects[i].shape);
}

TEST(MeshJson, InlineCubeWithQuadFacesIsAClosedSolid) {
    const Scene s =
        parse_scene(mesh_scene_with(std::string(R"({"type": "mesh", )") + kCubeVertices + ", " +
                                    kCubeFaces + R"(, "material": {"transparency": 1}})"));
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(s.objects[0].type, ObjectType::Mesh);
    const TriangleMesh& m = mesh_of(s, 0);
    EXPECT_TRUE(m.is_closed());
    EXPECT_EQ(m.triangle_count(), 12u);  // six quads, two triangles each
    EXPECT_EQ(m.vertex_count(), 8u);
    SurfaceHit h;
    ASSERT_TRUE(m.intersect({{0.3, 0.6, 5}, {0, 0, -1}}, 0, INFINITY, h));
    EXPECT_DOUBLE_EQ(h.t, 4.0);
    EXPECT_EQ(h.normal.z, 1.0);
    // From inside, the exit through the bottom: the normal still points out of the solid.
    ASSERT_TRUE(m.intersect({{0.3, 0.6, 0.5}, {0, 0, -1}}, 0, INFINITY, h));
    EXPECT_DOUBLE_EQ(h.t, 0.5);
    EXPECT_EQ(h.normal.z, -1.0);
}

// Every refracted direction in a ray tree, depth first.
void collect(const RayTreeNode& n, std::vector<std::pair<Vec3, double>>& out) {
    out.push_back({n.direction, n.weight});
    for (const RayTreeNode& c : n.children) collect(c, out);
}

TEST(MeshJson, InsideOutMeshIsTurnedOutwardAndRefractsTheSame) {
    const std::string material = R"(, "material": {"color": 1, "transparency": 1, "ior": 1.5}})";
    const Scene right = parse_scene(mesh_scene_with(std::string(R"({"type": "mesh", )") +
                                                    kCubeVertices + ", " + kCubeFaces + material));
    const Scene inverted =
        parse_scene(mesh_scene_with(std::string(R"({"type": "mesh", )") + kCubeVertices + ", " +
                                    kCubeFacesInsideOut + material));
    SurfaceHit h;
    ASSERT_TRUE(mesh_of(inverted, 0).intersect({{0.5, 0.5, 5}, {0, 0, -1}}, 0, INFINITY, h));
    EXPECT_EQ(h.normal.z, 1.0) << "the inside-out cube was not turned outward";

    // An oblique ray: enters the top, refracts towards the normal, leaves through a side.
    const Ray ray{{-0.5, 0.5, 2}, normalize(Vec3{1, 0.2, -1.6})};
    const RayTree a = trace_ray_tree(right, ray, {});
    const RayTree b = trace_ray_tree(inverted, ray, {});
    std::vector<std::pair<Vec3, double>> pa, pb;
    collect(a.root, pa);
    collect(b.root, pb);
    ASSERT_EQ(pa.size(), pb.size());
    ASSERT_GT(pa.size(), 4u);
    for (size_t i = 0; i < pa.size(); ++i) {
        EXPECT_NEAR(length(pa[i].first - pb[i].first), 0.0, 1e-12) << i;
        EXPECT_NEAR(pa[i].second, pb[i].second, 1e-12) << i;
    }
    // Snell at the top face: sin(theta_t) = sin(theta_i) / 1.5.
    ASSERT_EQ(a.root.children.size(), 2u);  // reflected, refracted at the top face
    EXPECT_EQ(a.root.children[1].event, Event::Refract);
    const Vec3 t = a.root.children[1].direction;
    const double sin_i = length(cross(ray.direction, Vec3{0, 0, 1}));
    EXPECT_NEAR(length(cross(t, Vec3{0, 0, 1})), sin_i / 1.5, 1e-12);
}

TEST(MeshJson, OpenMeshIsAcceptedOnlyWhenOpaque) {
    // The cube without its top: a box of two-sided squares.
    const std::string open_faces =
        R"("faces": [[0,3,2,1], [0,1,5,4], [2,3,7,6], [0,4,7,3], [1,2,6,5]])";
    const Scene s =
        parse_scene(mesh_scene_with(std::string(R"({"type": "mesh", )") + kCubeVertices + ", " +
                                    open_faces + R"(, "material": {"specular": 0.5}})"));
    const TriangleMesh& m = mesh_of(s, 0);
    EXPECT_FALSE(m.is_closed());
    EXPECT_EQ(m.open_reason(),
              "edge (5, 4) belongs to 1 face (face 1): the surface has a hole there");
    SurfaceHit h;
    EXPECT_TRUE(
        m.intersect({{0.5, 0.5, 0.5}, {0, 0, -1}}, 0, INFINITY, h));  // the floor, from above

    try {
        (void)parse_scene(mesh_scene_with(std::string(R"({"type": "mesh", )") + kCubeVertices +
                                          ", " + open_faces +
                                          R"(, "material": {"transparency": 0.2}})"));
        FAIL() << "a transparent open mesh was accepted";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.path(), "objects[0].faces");
        EXPECT_EQ(e.reason().rfind("the mesh is not closed: edge (5, 4) belongs to 1 face", 0), 0u)
            << e.reason();
    }
}

TEST(MeshJson, PlacementScalesRotatesThenMoves) {
    // Model +y goes to +z (up), model +z to -y (facing), so model +x stays +x.
    const Scene s = parse_scene(mesh_scene_with(
        std::string(R"({"type": "mesh", )") + kCubeVertices + ", " + kCubeFaces +
        R"(, "scale": 2, "up": [0, 0, 3], "facing": [0, -1, 0], "position": [10, 0, 0],
             "material": {"transparency": 1}})"));
    const Aabb b = mesh_of(s, 0).bounds();
    EXPECT_NEAR(length(b.lo - Vec3{10, -2, 0}), 0.0, 1e-12);
    EXPECT_NEAR(length(b.hi - Vec3{12, 0, 2}), 0.0, 1e-12);
    EXPECT_TRUE(mesh_of(s, 0).is_closed());
    SurfaceHit h;  // still outward after the rotation
    ASSERT_TRUE(mesh_of(s, 0).intersect({{11, -1, 5}, {0, 0, -1}}, 0, INFINITY, h));
    EXPECT_NEAR(h.normal.z, 1.0, 1e-15);
}

TEST(MeshJson, ObjFileIsFoundNextToTheSceneFile) {
    // ctest runs in the build tree; the scene names "wedge.obj" relative to its own folder.
    ASSERT_FALSE(fs::exists("wedge.obj"));
    const Scene s = load_scene_file(kDataDir + "/wedge_scene.json");
    const TriangleMesh& m = mesh_of(s, 0);
    EXPECT_TRUE(m.is_closed());
    EXPECT_EQ(m.triangle_count(), 8u);  // 2 triangles + 3 quads

    // It is the same solid as the prism shorthand.
    const Scene p = parse_scene(mesh_scene_with(
        R"({"type": "prism", "apex_angle": 60, "side": 1, "height": 1, "center": [0, 0, 0],
            "material": {"transparency": 1}})"));
    const Aabb a = m.bounds(), b = p.objects[0].shape->bounds();
    EXPECT_NEAR(length(a.lo - b.lo), 0.0, 1e-15);
    EXPECT_NEAR(length(a.hi - b.hi), 0.0, 1e-15);
    for (const Ray& r : {Ray{{-2, 0.1, 0.05}, {1, 0, 0}}, Ray{{0.1, 0.2, 3}, {0, 0, -1}},
                         Ray{{0.05, -3, 0}, {0, 1, 0}}}) {
        SurfaceHit ha, hb;
        ASSERT_TRUE(m.intersect(r, 0, INFINITY, ha));
        ASSERT_TRUE(p.objects[0].shape->intersect(r, 0, INFINITY, hb));
        EXPECT_NEAR(ha.t, hb.t, 1e-12);
        EXPECT_NEAR(length(ha.normal - hb.normal), 0.0, 1e-12);
    }
}

TEST(MeshJson, ParseSceneTakesTheFolderForRelativePaths) {
    std::ifstream in(kDataDir + "/wedge_scene.json");
    std::ostringstream text;
    text << in.rdbuf();
    EXPECT_NO_THROW(parse_scene(text.str(), "wedge", kDataDir));
    EXPECT_NO_THROW(scene_from_json(parse_json_strict(text.str(), "wedge"), kDataDir));
    // Without it, relative paths are relative to the current directory.
    try {
        (void)parse_scene(text.str());
        FAIL() << "wedge.obj was found in the current directory";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.path(), "objects[0].file");
        EXPECT_EQ(e.reason().rfind("cannot read 'wedge.obj': ", 0), 0u) << e.reason();
    }
    // An absolute path needs no folder.
    EXPECT_NO_THROW(
        parse_scene(mesh_scene_with(R"({"type": "mesh", "file": ")" + kDataDir +
                                    R"(/wedge.obj", "material": {"transparency": 1}})")));
}

// Problems inside an OBJ file name the file, and its faces and vertices as the file numbers
// them (from 1).
TEST(MeshJson, ObjProblemsNameTheFileAndCountFromOne) {
    const fs::path dir = fs::path(::testing::TempDir()) / "lenslab_mesh_json";
    fs::create_directories(dir);
    auto reason_for = [&](const std::string& obj_text, const std::string& material) {
        std::ofstream(dir / "t.obj") << obj_text;
        try {
            (void)parse_scene(mesh_scene_with(R"({"type": "mesh", "file": "t.obj", "material": )" +
                                              material + "}"),
                              "t", dir.string());
        } catch (const SceneError& e) {
            EXPECT_EQ(e.path(), "objects[0].file");
            return e.reason();
        }
        return std::string("loaded");
    };
    const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    EXPECT_EQ(reason_for(tri + "f 1 2 9\n", "{}"),
              "t.obj:4: face 1 refers to vertex 9, but only 3 vertices are defined before this "
              "line");
    EXPECT_EQ(reason_for(tri, "{}"), "cannot read 't.obj': it has no faces (f lines)");
    EXPECT_EQ(reason_for(tri + "f 1 2 2\n", "{}"), "t.obj:4: face 1 uses vertex 2 twice");
    // What tinyobjloader, the reader before lenslab's own, took silently: NaN and infinite or
    // unreadable coordinates as 0, fractional indices truncated, an index beyond the integer
    // range wrapped round to another vertex, a two-corner face dropped, and a negative index
    // reported with another number. Each is refused at its line.
    EXPECT_EQ(reason_for("# a comment\r\n\r\nv nan 0 0\r\n", "{}"),
              "t.obj:3: vertex coordinate 'nan' is not a finite number");
    EXPECT_EQ(reason_for("v 0 inf 0\n", "{}"),
              "t.obj:1: vertex coordinate 'inf' is not a finite number");
    EXPECT_EQ(reason_for("v abc def ghi\n", "{}"),
              "t.obj:1: vertex coordinate 'abc' is not a number");
    EXPECT_EQ(reason_for(tri + "f 1.7 2.2 3.9\n", "{}"),
              "t.obj:4: vertex index '1.7' is not a whole number");
    EXPECT_EQ(reason_for(tri + "f 1 2 3\nf 1 2 4294967299\n", "{}"),
              "t.obj:5: vertex index '4294967299' is beyond the integer range");
    EXPECT_EQ(reason_for(tri + "f 1 2 3\nf 1 2\n", "{}"),
              "t.obj:5: a face needs at least 3 corners, got 2");
    EXPECT_EQ(reason_for(tri + "v 1 1 0\nf -9 -2 -1\n", "{}"),
              "t.obj:5: face 1 refers to vertex -9, but only 4 vertices are defined before this "
              "line (-1 is the last, -4 the first)");
    // One triangle is an open surface: fine when opaque, refused when transparent.
    EXPECT_EQ(reason_for(tri + "f 1 2 3\n", R"({"color": 0.5})"), "loaded");
    EXPECT_EQ(reason_for(tri + "f -3 -2 -1\n", R"({"transparency": 1})")
                  .rfind("the mesh is not closed: edge (1, 2) belongs to 1 face (face 1)", 0),
              0u);
    EXPECT_EQ(reason_for("", "{}").rfind("cannot read 't.obj': it has no faces", 0), 0u);
    // The same triangle twice, in another order, or over repeated vertices: refused (a mesh
    // of 5,000,000 copies of `f 1 2 3` made every ray test them all, a minute for 32x32).
    const std::string same =
        ": a mesh holds each triangle once (coincident faces cannot be "
        "told apart)";
    EXPECT_EQ(reason_for(tri + "f 1 2 3\nf 1 2 3\n", "{}"),
              "faces 1 and 2 are the same triangle (vertices 1, 2, 3)" + same);
    EXPECT_EQ(reason_for(tri + "v 0 1 0\nf 1 2 3\nf 2 4 1\n", "{}"),
              "faces 1 and 2 are the same triangle (vertices 1, 2, 3)" + same);
    std::string copies = tri;
    for (int i = 0; i < 100000; ++i) copies += "f 1 2 3\n";
    EXPECT_EQ(reason_for(copies, "{}"),
              "faces 1 and 2 are the same triangle (vertices 1, 2, 3)" + same);
    // Facing the other way it is still the same triangle; two sharing an edge are not.
    EXPECT_EQ(reason_for(tri + "f 1 2 3\nf 1 3 2\n", R"({"color": 0.5})"),
              "faces 1 and 2 are the same triangle (vertices 1, 2, 3)" + same);
    EXPECT_EQ(reason_for(tri + "v 1 1 0\nf 1 2 3\nf 2 4 3\n", R"({"color": 0.5})"), "loaded");
    try {
        (void)parse_scene(
            mesh_scene_with(R"({"type": "mesh", "file": "absent.obj", "material": {}})"), "t",
            dir.string());
        FAIL() << "a missing OBJ file was accepted";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.reason(), "cannot read 'absent.obj': No such file or directory (looked for " +
                                  (dir / "absent.obj").string() + ")");
    }
}

TEST(MeshJson, PrismFacesAreWhereTheDocumentationSays) {
    // Apex 60, side 2: apex-to-base 2 cos 30 = sqrt(3), half base 1. Axis +y, facing +z,
    // centre (0, 1, 0): apex edge at z = sqrt(3)/2, base at z = -sqrt(3)/2, x in [-1, 1].
    const Scene s = parse_scene(mesh_scene_with(
        R"({"type": "prism", "side": 2, "height": 0.5, "center": [0, 1, 0],
            "material": {"transparency": 1, "ior": 1.5}})"));
    const Aabb b = s.objects[0].shape->bounds();
    const double h = std::sqrt(3.0) / 2;
    EXPECT_NEAR(length(b.lo - Vec3{-1, 0.75, -h}), 0.0, 1e-12);
    EXPECT_NEAR(length(b.hi - Vec3{1, 1.25, h}), 0.0, 1e-12);
    SurfaceHit hit;
    ASSERT_TRUE(s.objects[0].shape->intersect({{0, 1, -5}, {0, 0, 1}}, 0, INFINITY, hit));
    EXPECT_NEAR(hit.t, 5 - h, 1e-12);  // the base
    EXPECT_NEAR(length(hit.normal - Vec3{0, 0, -1}), 0.0, 1e-12);
    ASSERT_TRUE(s.objects[0].shape->intersect({{0, 1, 5}, {0, 0, -1}}, 0, INFINITY, hit));
    EXPECT_NEAR(hit.t, 5 - h, 1e-12);  // the apex edge
}

}  // namespace
}  // namespace lenslab
