// Ray-object intersection throughput for each shape and for the default scene's BVH.

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "geometry/implicit_solid.h"
#include "geometry/lens/asphere_surface.h"
#include "geometry/lens/conic_surface.h"
#include "geometry/lens/lens_solid.h"
#include "geometry/lens/sag_formula_surface.h"
#include "geometry/lens/spherical_surface.h"
#include "geometry/sphere.h"
#include "geometry/triangle.h"
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
void BM_Triangle(benchmark::State& state) { run(state, Triangle({-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0, 0.5, 0})); }
void BM_Lens(benchmark::State& state) {
    run(state, LensSolid(LensSolid::symmetric_biconvex({0, 0, 0}, normalize(Vec3{1, 1, 0}), 1.0, 0.5)));
}

// The same lens as BM_Lens (R = +-1, aperture radius 0.5, knife edge) with its faces written
// as other surface kinds: the cost of each kind against the analytic sphere's
// (docs/performance.md, "Equation-defined surfaces").
LensPrescription report_lens_with(std::shared_ptr<const LensSurface> front,
                                  std::shared_ptr<const LensSurface> back) {
    LensPrescription p = LensSolid::symmetric_biconvex({0, 0, 0}, normalize(Vec3{1, 1, 0}), 1.0, 0.5);
    p.front = std::move(front);
    p.back = std::move(back);
    return p;
}
void BM_LensConic(benchmark::State& state) {
    run(state, LensSolid(report_lens_with(std::make_shared<ConicSurface>(1.0, 0.0),
                                          std::make_shared<ConicSurface>(-1.0, 0.0))));
}
void BM_LensAsphere(benchmark::State& state) {
    run(state, LensSolid(report_lens_with(std::make_shared<AsphereSurface>(1.0, 0.0, std::vector<double>{0.0}),
                                          std::make_shared<AsphereSurface>(-1.0, 0.0, std::vector<double>{0.0}))));
}
void BM_LensSagFormula(benchmark::State& state) {
    run(state, LensSolid(report_lens_with(std::make_shared<SagFormulaSurface>("1 - sqrt(1 - r^2)", 0.5),
                                          std::make_shared<SagFormulaSurface>("sqrt(1 - r^2) - 1", 0.5))));
}
// A sphere of radius 0.5 written as an implicit equation, against BM_Sphere.
void BM_ImplicitSphere(benchmark::State& state) {
    run(state, ImplicitSolid("x^2 + y^2 + z^2 - 0.25", {{-0.55, -0.55, -0.55}, {0.55, 0.55, 0.55}}));
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
BENCHMARK(BM_LensConic);
BENCHMARK(BM_LensAsphere);
BENCHMARK(BM_LensSagFormula);
BENCHMARK(BM_ImplicitSphere);
BENCHMARK(BM_DefaultSceneBvh);

}  // namespace
}  // namespace lenslab
