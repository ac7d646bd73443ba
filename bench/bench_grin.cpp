// Gradient-index transport: one ray through a Luneburg lens (with the integrator's steps per
// ray as a counter), and a 640x480 render of scenes/luneburg_lens.json.

#include <benchmark/benchmark.h>

#include <cmath>

#include "render/integrator_names.h"
#include "render/render_session.h"
#include "scene/interaction.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

void BM_GrinLuneburgRay(benchmark::State& state) {
    const Scene scene = load_scene_file(LENSLAB_SOURCE_DIR "/scenes/luneburg_lens.json");
    const SceneObject& lens = scene.objects[0];
    const GrinMedium medium = grin_medium_of(lens, scene.materials[lens.material], kLineD);
    int64_t steps = 0, rays = 0;
    for (auto _ : state) {
        // Across the aperture, entering at z = -sqrt(1 - x^2).
        const double x = 0.9 * double(rays % 19) / 18.0;
        const GrinExit exit =
            trace_grin_ray(medium, *lens.shape, {x, 0, -std::sqrt(1 - x * x)}, {0, 0, 1});
        benchmark::DoNotOptimize(exit);
        steps += exit.steps;
        ++rays;
    }
    state.counters["steps_per_ray"] = double(steps) / double(rays);
}

BENCHMARK(BM_GrinLuneburgRay);

void BM_GrinLuneburgRender(benchmark::State& state) {
    Scene scene = load_scene_file(LENSLAB_SOURCE_DIR "/scenes/luneburg_lens.json");
    scene.render.integrator = integrators::kWhitted;
    scene.render.width = 640;
    scene.render.height = 480;
    scene.render.spp = 1;
    for (auto _ : state) {
        RenderControl control;
        benchmark::DoNotOptimize(render_scene(scene, control, static_cast<int>(state.range(0))));
    }
}

BENCHMARK(BM_GrinLuneburgRender)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace lenslab
