// Whole renders of the default scene with the whitted integrator, and one sppm pass, single-
// threaded and on every core, so the thread speed-up shows in one run.

#include <benchmark/benchmark.h>

#include "render/integrator_names.h"
#include "render/progressive_render.h"
#include "render/render_session.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

void BM_WhittedDefaultScene(benchmark::State& state) {
    Scene scene = default_scene();
    scene.render.integrator = integrators::kWhitted;
    scene.render.width = 200;
    scene.render.height = 150;
    scene.render.spp = 4;
    for (auto _ : state) {
        RenderControl control;
        benchmark::DoNotOptimize(render_scene(scene, control, static_cast<int>(state.range(0))));
    }
    state.SetItemsProcessed(state.iterations() * scene.render.width * scene.render.height *
                            scene.render.spp);
}

BENCHMARK(BM_WhittedDefaultScene)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace lenslab

namespace lenslab {
namespace {

// One sppm pass of the default scene at 400x300 (camera paths, 120 000 photons, gather and
// update), single-threaded and on every core.
void BM_SppmPassDefaultScene(benchmark::State& state) {
    Scene scene = default_scene();
    scene.render.integrator = integrators::kSppm;
    scene.render.width = 400;
    scene.render.height = 300;
    ProgressiveRender render(scene, static_cast<int>(state.range(0)));
    RenderControl control;
    for (auto _ : state) render.add_pass(control);
    state.SetItemsProcessed(state.iterations() * scene.render.width * scene.render.height);
    state.counters["photons/s"] = benchmark::Counter(static_cast<double>(render.stats(0).photons),
                                                     benchmark::Counter::kIsRate);
}

BENCHMARK(BM_SppmPassDefaultScene)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace lenslab
