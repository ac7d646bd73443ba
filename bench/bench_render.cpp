// Whole renders of the default scene with the whitted integrator, single-threaded and on
// every core, so the thread speed-up shows in one run.

#include <benchmark/benchmark.h>

#include "render/render_session.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

void BM_WhittedDefaultScene(benchmark::State& state) {
    Scene scene = default_scene();
    scene.render.integrator = "whitted";
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
