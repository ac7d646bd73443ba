// The model of one redraw of the editor's section view of the default lens: the
// cross-sections of every object the plane cuts and 15 rays across the lens (the d line
// only: the default glass does not disperse), with or without the lamp's fan, traced
// through the whole scene and turned into the drawing. The painting is measured by
// lenslab_gui_bench (bench_section_redraw.cpp). The issue asks for under 20 ms a frame.

#include <benchmark/benchmark.h>

#include "analysis/section/section_view.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

void BM_SectionViewDefaultLens(benchmark::State& state) {
    const Scene scene = default_scene();
    const int lens = 1;  // "glass lens"
    const SectionPlane plane = default_section_plane(scene, lens);
    SectionViewOptions options;  // as the editor draws it
    options.rays.beam = default_section_beam(scene, lens, plane, 15);
    options.rays.rays_per_light = static_cast<int>(state.range(0));
    size_t paths = 0;
    for (auto _ : state) {
        const SectionView view = make_section_view(scene, plane, options);
        const RayDiagram d = section_diagram(scene, view, lens);
        paths = d.paths.size();
        benchmark::DoNotOptimize(paths);
    }
    state.counters["paths"] = double(paths);
}

// 0: the 15 beam rays alone; 12: with the lamp's fan, as the editor shows it.
BENCHMARK(BM_SectionViewDefaultLens)->Arg(0)->Arg(12)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace lenslab
