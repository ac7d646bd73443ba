// Ray-object intersection throughput for each shape, for a 100k-triangle mesh (its own BVH,
// and the same triangles as separate shapes in the generic scene BVH for comparison), and
// for the default scene's BVH.

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "geometry/bvh.h"
#include "geometry/implicit_solid.h"
#include "geometry/lens/asphere_surface.h"
#include "geometry/lens/conic_surface.h"
#include "geometry/lens/lens_solid.h"
#include "geometry/lens/sag_formula_surface.h"
#include "geometry/lens/spherical_surface.h"
#include "geometry/mesh_shapes.h"
#include "geometry/sphere.h"
#include "geometry/triangle.h"
#include "geometry/triangle_mesh.h"
#include "math/rng.h"
#include "math/sampling.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

// Rays from a sphere of radius 5 aimed at random points of the unit cube around the origin.
std::vector<Ray> random_rays(int n) {
    Rng rng(1, 0);
    std::vector<Ray> rays(n);
    for (Ray& r : rays) {
        r.origin = sample_uniform_sphere(rng.uniform(), rng.uniform()) * 5.0;
        const Vec3 target{rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5};
        r.direction = normalize(target - r.origin);
    }
    return rays;
}

void run(benchmark::State& state, const Shape& shape) {
    const auto rays = random_rays(4096);
    size_t i = 0, hits = 0;
    SurfaceHit h;
    for (auto _ : state) {
        hits += shape.intersect(rays[i++ & 4095], 0, INFINITY, h);
        benchmark::DoNotOptimize(h);
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["hit_fraction"] = double(hits) / state.iterations();
}

void BM_Sphere(benchmark::State& state) { run(state, Sphere({0, 0, 0}, 0.5)); }
void BM_Triangle(benchmark::State& state) {
    run(state, Triangle({-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0, 0.5, 0}));
}
void BM_Lens(benchmark::State& state) {
    run(state,
        LensSolid(LensSolid::symmetric_biconvex({0, 0, 0}, normalize(Vec3{1, 1, 0}), 1.0, 0.5)));
}

// A UV sphere of radius 0.5 with 250 x 201 bands: 100,000 triangles.
MeshGeometry sphere_100k() { return make_uv_sphere({0, 0, 0}, 0.5, 250, 201); }

void BM_Mesh100k(benchmark::State& state) {
    const MeshGeometry g = sphere_100k();
    const TriangleMesh mesh(g.vertices, g.triangles, true);
    state.counters["triangles"] = static_cast<double>(mesh.triangle_count());
    run(state, mesh);
}

// Rays that start inside the mesh and look for the way out (every one hits).
void BM_Mesh100kFromInside(benchmark::State& state) {
    const MeshGeometry g = sphere_100k();
    const TriangleMesh mesh(g.vertices, g.triangles, true);
    Rng rng(2, 0);
    std::vector<Ray> rays(4096);
    for (Ray& r : rays) {
        r.origin = Vec3{rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5} * 0.5;
        r.direction = sample_uniform_sphere(rng.uniform(), rng.uniform());
    }
    size_t i = 0, hits = 0;
    SurfaceHit h;
    for (auto _ : state) {
        hits += mesh.intersect(rays[i++ & 4095], 0, INFINITY, h);
        benchmark::DoNotOptimize(h);
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["hit_fraction"] = double(hits) / state.iterations();
}

// The same triangles as 100,000 Triangle shapes in the scene's generic BVH (virtual calls,
// pointer chasing): what the mesh's own BVH is measured against.
void BM_Mesh100kAsShapesInGenericBvh(benchmark::State& state) {
    const MeshGeometry g = sphere_100k();
    std::vector<Triangle> triangles;
    triangles.reserve(g.triangles.size());
    for (const MeshTriangle& t : g.triangles) {
        triangles.emplace_back(g.vertices[t[0]], g.vertices[t[1]], g.vertices[t[2]]);
    }
    std::vector<const Shape*> shapes;
    for (const Triangle& t : triangles) shapes.push_back(&t);
    const Bvh bvh(shapes);
    const auto rays = random_rays(4096);
    size_t i = 0, hits = 0;
    BvhHit h;
    for (auto _ : state) {
        hits += bvh.intersect(rays[i++ & 4095], 0, INFINITY, h);
        benchmark::DoNotOptimize(h);
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["hit_fraction"] = double(hits) / state.iterations();
}

void BM_Mesh100kBuild(benchmark::State& state) {
    const MeshGeometry g = sphere_100k();
    for (auto _ : state) {
        const TriangleMesh mesh(g.vertices, g.triangles, true);
        benchmark::DoNotOptimize(mesh.bounds());
    }
}

// The same lens as BM_Lens (R = +-1, aperture radius 0.5, knife edge) with its faces written
// as other surface kinds: the cost of each kind against the analytic sphere's
// (docs/performance.md, "Equation-defined surfaces").
LensPrescription report_lens_with(std::shared_ptr<const LensSurface> front,
                                  std::shared_ptr<const LensSurface> back) {
    LensPrescription p =
        LensSolid::symmetric_biconvex({0, 0, 0}, normalize(Vec3{1, 1, 0}), 1.0, 0.5);
    p.front = std::move(front);
    p.back = std::move(back);
    return p;
}
void BM_LensConic(benchmark::State& state) {
    run(state, LensSolid(report_lens_with(std::make_shared<ConicSurface>(1.0, 0.0),
                                          std::make_shared<ConicSurface>(-1.0, 0.0))));
}
void BM_LensAsphere(benchmark::State& state) {
    run(state, LensSolid(report_lens_with(
                   std::make_shared<AsphereSurface>(1.0, 0.0, std::vector<double>{0.0}),
                   std::make_shared<AsphereSurface>(-1.0, 0.0, std::vector<double>{0.0}))));
}
void BM_LensSagFormula(benchmark::State& state) {
    run(state,
        LensSolid(report_lens_with(std::make_shared<SagFormulaSurface>("1 - sqrt(1 - r^2)", 0.5),
                                   std::make_shared<SagFormulaSurface>("sqrt(1 - r^2) - 1", 0.5))));
}
// A sphere of radius 0.5 written as an implicit equation, against BM_Sphere.
void BM_ImplicitSphere(benchmark::State& state) {
    run(state,
        ImplicitSolid("x^2 + y^2 + z^2 - 0.25", {{-0.55, -0.55, -0.55}, {0.55, 0.55, 0.55}}));
}

void BM_DefaultSceneBvh(benchmark::State& state) {
    const Scene scene = default_scene();
    const auto rays = random_rays(4096);
    size_t i = 0;
    SceneHit h;
    for (auto _ : state) {
        Ray r = rays[i++ & 4095];
        r.origin = r.origin + Vec3{0, 1, 0};  // the scene stands on y = 0
        benchmark::DoNotOptimize(scene.intersect(r, 0, INFINITY, h));
    }
    state.SetItemsProcessed(state.iterations());
}

BENCHMARK(BM_Sphere);
BENCHMARK(BM_Triangle);
BENCHMARK(BM_Lens);
BENCHMARK(BM_Mesh100k);
BENCHMARK(BM_Mesh100kFromInside);
BENCHMARK(BM_Mesh100kAsShapesInGenericBvh);
BENCHMARK(BM_Mesh100kBuild)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LensConic);
BENCHMARK(BM_LensAsphere);
BENCHMARK(BM_LensSagFormula);
BENCHMARK(BM_ImplicitSphere);
BENCHMARK(BM_DefaultSceneBvh);

}  // namespace
}  // namespace lenslab
