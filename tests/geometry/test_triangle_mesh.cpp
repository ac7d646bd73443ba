// Triangle meshes: the mesh's BVH against brute force, watertightness on shared edges, the
// closedness and orientation check, and the property every solid must have: a ray that
// entered it finds its way out.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "geometry/mesh_shapes.h"
#include "geometry/mesh_topology.h"
#include "geometry/triangle.h"
#include "geometry/triangle_mesh.h"
#include "math/rng.h"
#include "math/sampling.h"
#include "optics/refraction.h"

namespace lenslab {
namespace {

std::vector<int32_t> one_face_per_triangle(const MeshGeometry& g) {
    std::vector<int32_t> f(g.triangles.size());
    for (size_t i = 0; i < f.size(); ++i) f[i] = static_cast<int32_t>(i);
    return f;
}

TriangleMesh closed_mesh(const MeshGeometry& g) {
    const MeshTopology t = check_mesh_topology(g.vertices, g.triangles, one_face_per_triangle(g));
    EXPECT_TRUE(t.closed) << t.problem;
    EXPECT_GT(t.signed_volume, 0.0);
    return TriangleMesh(g.vertices, g.triangles, t.closed);
}

// A random ray from a sphere of radius 3 around `box` aimed at a random point inside it.
Ray ray_towards(const Aabb& box, Rng& rng) {
    const Vec3 c = box.centre();
    const Vec3 e = box.extent();
    const double r = 3.0 * std::max(e.x, std::max(e.y, e.z));
    const Vec3 origin = c + sample_uniform_sphere(rng.uniform(), rng.uniform()) * r;
    const Vec3 target =
        box.lo + Vec3{e.x * rng.uniform(), e.y * rng.uniform(), e.z * rng.uniform()};
    return {origin, normalize(target - origin)};
}

TEST(MeshShapes, PrismAndSphereAreClosedAndFaceOutward) {
    // Prism volume: cross-section area side^2 sin(A) / 2 times the height.
    const PrismSpec spec{60.0, 2.0, 3.0, {1, 2, 3}, {0, 1, 0}, {0, 0, 1}};
    const MeshGeometry prism = make_prism(spec);
    const MeshTopology tp =
        check_mesh_topology(prism.vertices, prism.triangles, one_face_per_triangle(prism));
    ASSERT_TRUE(tp.closed) << tp.problem;
    EXPECT_NEAR(tp.signed_volume, 0.5 * 4.0 * std::sin(std::numbers::pi / 3) * 3.0, 1e-12);

    // A UV sphere is inscribed: its volume approaches 4/3 pi r^3 from below.
    const MeshGeometry sphere = make_uv_sphere({0, 0, 0}, 1.0, 64, 32);
    EXPECT_EQ(sphere.triangles.size(), 2u * 64 * 31);
    const MeshTopology ts =
        check_mesh_topology(sphere.vertices, sphere.triangles, one_face_per_triangle(sphere));
    ASSERT_TRUE(ts.closed) << ts.problem;
    EXPECT_LT(ts.signed_volume, 4.0 / 3.0 * std::numbers::pi);
    EXPECT_GT(ts.signed_volume, 0.99 * 4.0 / 3.0 * std::numbers::pi);
}

TEST(MeshShapes, PrismCornersAreWhereDocumented) {
    // Apex 90 degrees, side 2: apex-to-base d = sqrt(2), half base b = sqrt(2).
    const PrismSpec spec{90.0, 2.0, 4.0, {10, 0, 0}, {0, 0, 1}, {1, 0, 0}};
    const MeshGeometry m = make_prism(spec);
    const double s = std::sqrt(2.0);
    const Vec3 w = cross(spec.axis, spec.facing);  // (0, 1, 0)
    const Vec3 expected[6] = {
        {10 + s / 2, 0, -2}, Vec3{10 - s / 2, 0, -2} - w * s, Vec3{10 - s / 2, 0, -2} + w * s,
        {10 + s / 2, 0, 2},  Vec3{10 - s / 2, 0, 2} - w * s,  Vec3{10 - s / 2, 0, 2} + w * s};
    for (int i = 0; i < 6; ++i) {
        EXPECT_NEAR(length(m.vertices[i] - expected[i]), 0.0, 1e-12) << "vertex " << i;
    }
}

TEST(TriangleMesh, NearestHitMatchesBruteForce) {
    const MeshGeometry g = make_uv_sphere({0.2, -0.1, 0.3}, 0.8, 24, 12);
    const TriangleMesh mesh = closed_mesh(g);
    std::vector<Triangle> triangles;
    for (const MeshTriangle& t : g.triangles) {
        triangles.emplace_back(g.vertices[t[0]], g.vertices[t[1]], g.vertices[t[2]]);
    }
    Rng rng(7, 0);
    int hits = 0;
    for (int q = 0; q < 4000; ++q) {
        const Ray ray = ray_towards(mesh.bounds(), rng);
        double best = INFINITY;
        Vec3 normal;
        for (const Triangle& t : triangles) {
            SurfaceHit h;
            if (t.intersect(ray, 1e-9, best, h)) {
                best = h.t;
                normal = h.normal;
            }
        }
        SurfaceHit h;
        const bool found = mesh.intersect(ray, 1e-9, INFINITY, h);
        ASSERT_EQ(found, std::isfinite(best)) << q;
        if (!found) continue;
        ++hits;
        EXPECT_NEAR(h.t, best, 1e-9 * best);
        EXPECT_NEAR(length(h.normal - normal), 0.0, 1e-9);
        EXPECT_NEAR(length(h.point - ray.at(best)), 0.0, 1e-9);
    }
    EXPECT_GT(hits, 2000);
}

TEST(TriangleMesh, AxisAlignedRaysHitWhateverTheSignOfTheirZeros) {
    // A direction component of -0 makes 1/d = -inf: the box test must take the far side first.
    const TriangleMesh mesh = closed_mesh(make_prism({}));
    for (const Vec3& d :
         {Vec3{1, 0, 0}, Vec3{1, -0.0, -0.0}, Vec3{-0.0, 1, 0}, Vec3{0, -0.0, -1}}) {
        SurfaceHit h;
        EXPECT_TRUE(mesh.intersect({d * -3.0 + Vec3{0, 0.1, 0.01}, d}, 0, INFINITY, h))
            << d.x << " " << d.y << " " << d.z;
    }
}

TEST(TriangleMesh, RaysThroughSharedEdgesAndVerticesNeverSlipThrough) {
    // An octahedron: rays aimed at its centre through the midpoint of every edge and through
    // every vertex meet exactly the boundary between faces, where a non-watertight test can
    // miss both triangles.
    const MeshGeometry g{
        {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}},
        {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}};
    const TriangleMesh mesh = closed_mesh(g);
    std::vector<Vec3> targets(g.vertices);
    for (const MeshTriangle& t : g.triangles) {
        for (int k = 0; k < 3; ++k)
            targets.push_back((g.vertices[t[k]] + g.vertices[t[(k + 1) % 3]]) * 0.5);
    }
    Rng rng(3, 0);
    for (const Vec3& target : targets) {
        for (int q = 0; q < 200; ++q) {
            // From outside through the boundary point (within its cone of inward directions),
            // and from near the centre out through it.
            const Vec3 out = normalize(normalize(target) +
                                       sample_uniform_sphere(rng.uniform(), rng.uniform()) * 0.3);
            const Vec3 from = target + out * (0.5 + 5.0 * rng.uniform());
            SurfaceHit h;
            EXPECT_TRUE(mesh.intersect({from, normalize(target - from)}, 0, INFINITY, h));
            const Vec3 inner =
                Vec3{rng.uniform(), rng.uniform(), rng.uniform()} * 0.1 - Vec3{0.05, 0.05, 0.05};
            EXPECT_TRUE(mesh.intersect({inner, normalize(target - inner)}, 0, INFINITY, h));
            EXPECT_GT(dot(normalize(target - inner), h.normal), 0.0);
        }
    }
}

// 10^5 rays enter the solid (refracted with n = 1.5) and are followed inside, reflecting off
// the faces where total internal reflection holds, until they leave. At every step each one
// must find the surface from inside (normal along the ray) at a finite point within the
// bounds: no ray leaks out between triangles or stops inside. Nearly all then leave by
// refraction; a faceted sphere traps a few grazing rays in whispering-gallery orbits (their
// internal angle sits just past the critical angle on every facet), which is optics, not a
// leak: `max_trapped` allows for them.
void every_entering_ray_exits(const TriangleMesh& mesh, uint64_t seed, int max_trapped) {
    const double eta = 1.5;
    Rng rng(seed, 0);
    int entered = 0, exited = 0, steps = 0;
    const Aabb box = mesh.bounds();
    const Vec3 slack = box.extent() * 1e-9;
    while (entered < 100000) {
        const Ray ray = ray_towards(box, rng);
        SurfaceHit h;
        if (!mesh.intersect(ray, 0, INFINITY, h)) continue;
        ASSERT_LT(dot(ray.direction, h.normal), 0.0)
            << "the first hit from outside must be an entry";
        const auto inside = refract(ray.direction, h.normal, 1.0 / eta);
        ASSERT_TRUE(inside.has_value());
        ++entered;
        Ray r{h.point, *inside};
        for (int bounce = 0; bounce < 1000; ++bounce) {
            SurfaceHit exit;
            ASSERT_TRUE(mesh.intersect(r, surface_epsilon(r.origin), INFINITY, exit))
                << "ray " << entered << " found no way out after " << bounce << " reflections";
            ++steps;
            ASSERT_TRUE(std::isfinite(exit.t) && is_finite(exit.point) && is_finite(exit.normal));
            ASSERT_GT(dot(r.direction, exit.normal), 0.0) << "a hit from inside must be an exit";
            ASSERT_TRUE(exit.point.x >= box.lo.x - slack.x && exit.point.x <= box.hi.x + slack.x &&
                        exit.point.y >= box.lo.y - slack.y && exit.point.y <= box.hi.y + slack.y &&
                        exit.point.z >= box.lo.z - slack.z && exit.point.z <= box.hi.z + slack.z);
            if (refract(r.direction, -exit.normal, eta)) {
                ++exited;
                break;
            }
            r = {exit.point, reflect(r.direction, exit.normal)};  // total internal reflection
        }
    }
    EXPECT_GE(exited, entered - max_trapped);
    ::testing::Test::RecordProperty("internal_segments", steps);
    ::testing::Test::RecordProperty("trapped", entered - exited);
}

TEST(TriangleMesh, EveryRayEnteringAPrismExits) {
    every_entering_ray_exits(
        closed_mesh(make_prism({60.0, 1.0, 1.0, {0, 0, 0}, {0, 1, 0}, {0, 0, 1}})), 11, 0);
    every_entering_ray_exits(
        closed_mesh(make_prism(
            {30.0, 2.0, 0.5, {1, 2, 3}, normalize(Vec3{1, 1, 0}), normalize(Vec3{1, -1, 1})})),
        12, 0);
}

TEST(TriangleMesh, EveryRayEnteringATessellatedSphereExits) {
    every_entering_ray_exits(closed_mesh(make_uv_sphere({0.3, 0, -0.2}, 1.0, 96, 48)), 13, 20);
}

TEST(MeshTopology, FindsHolesDisagreeingFacesAndNonManifoldEdges) {
    const MeshGeometry prism = make_prism({});
    std::vector<int32_t> faces = one_face_per_triangle(prism);

    MeshGeometry holed = prism;
    holed.triangles.pop_back();  // {1, 5, 2}, half of the base
    auto t = check_mesh_topology(holed.vertices, holed.triangles, faces);
    EXPECT_FALSE(t.closed);
    EXPECT_EQ(t.problem, "edge (1, 2) belongs to 1 face (face 0): the surface has a hole there");

    MeshGeometry twisted = prism;
    std::swap(twisted.triangles[1][1], twisted.triangles[1][2]);  // one end cap faces inward
    t = check_mesh_topology(twisted.vertices, twisted.triangles, faces);
    EXPECT_FALSE(t.closed);
    EXPECT_EQ(t.problem,
              "faces 1 and 2 both run along edge (3, 4) in the same direction: their "
              "orientations disagree");

    MeshGeometry fin = prism;
    fin.vertices.push_back({0, 0, 5});
    fin.triangles.push_back({0, 3, 6});  // a fin on the apex edge
    faces.push_back(8);
    t = check_mesh_topology(fin.vertices, fin.triangles, faces);
    EXPECT_FALSE(t.closed);
    EXPECT_EQ(t.problem.rfind("edge (0, 3) belongs to 3 faces", 0), 0u) << t.problem;

    // Numbered from 1, as an OBJ file numbers them.
    t = check_mesh_topology(holed.vertices, holed.triangles, faces, 1);
    EXPECT_EQ(t.problem, "edge (2, 3) belongs to 1 face (face 1): the surface has a hole there");
}

TEST(MeshTopology, InsideOutMeshHasNegativeVolumeAndRepeatedCornersWeld) {
    MeshGeometry prism = make_prism({});
    flip_triangles(prism.triangles);
    const auto t =
        check_mesh_topology(prism.vertices, prism.triangles, one_face_per_triangle(prism));
    EXPECT_TRUE(t.closed);
    EXPECT_LT(t.signed_volume, 0.0);

    // The same prism with every triangle owning its own corners (as many files store it).
    MeshGeometry soup;
    for (const MeshTriangle& tri : make_prism({}).triangles) {
        const auto base = static_cast<int32_t>(soup.vertices.size());
        for (int32_t k : tri) soup.vertices.push_back(prism.vertices[k]);
        soup.triangles.push_back({base, base + 1, base + 2});
    }
    const auto s = check_mesh_topology(soup.vertices, soup.triangles, one_face_per_triangle(soup));
    EXPECT_TRUE(s.closed) << s.problem;
    EXPECT_GT(s.signed_volume, 0.0);
}

}  // namespace
}  // namespace lenslab
