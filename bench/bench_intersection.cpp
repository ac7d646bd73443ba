// Ray-object intersection throughput for each shape and for the default scene's BVH.

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "geometry/lens/lens_solid.h"
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
BENCHMARK(BM_DefaultSceneBvh);

}  // namespace
}  // namespace lenslab
