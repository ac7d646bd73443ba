// Cancelling the photon pass: Ctrl-C must stop a chunk within a few hundred photons, not at
// its end (issue 15: 6 s to stop 30 million photons). Counted in photons, not seconds, so
// the checks hold on a loaded machine.

#include <gtest/gtest.h>
#include <tbb/info.h>

#include <atomic>

#include "render/photon_tracer.h"
#include "render/photon_walk.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

TEST(PhotonCancel, ARangeStopsWithinOneCheckIntervalOfTheCancel) {
    RenderControl control;
    constexpr int64_t kCancelAt = 1000;
    int64_t traced = 0;
    trace_photon_range(0, kPhotonChunk, control, [&](int64_t i) {
        ++traced;
        if (i == kCancelAt) control.cancel();
    });
    EXPECT_GT(traced, kCancelAt);
    EXPECT_LE(traced, kCancelAt + 1 + kPhotonCancelCheck);
}

TEST(PhotonCancel, AnUncancelledRangeTracesEveryPhotonInOrder) {
    RenderControl control;
    int64_t next = 100;
    trace_photon_range(100, 100 + 3 * kPhotonCancelCheck + 7, control, [&](int64_t i) {
        ASSERT_EQ(i, next);
        ++next;
    });
    EXPECT_EQ(next, 100 + 3 * kPhotonCancelCheck + 7);
}

TEST(PhotonCancel, CancelledBeforeTheStartTracesNothing) {
    RenderControl control;
    control.cancel();
    std::atomic<int64_t> traced{0};
    for_each_photon_chunk(int64_t{1} << 30, control, [&](int64_t, int64_t first, int64_t last) {
        trace_photon_range(first, last, control, [&](int64_t) { ++traced; });
    });
    EXPECT_EQ(traced.load(), 0);
}

TEST(PhotonCancel, ParallelChunksStopWithinOneCheckIntervalPerThread) {
    // A billion photons would take minutes; the cancel after 100,000 ends it, each running
    // chunk finishing at most one check interval past it.
    RenderControl control;
    constexpr int64_t kCancelAfter = 100000;
    std::atomic<int64_t> traced{0};
    std::atomic<int64_t> traced_after_cancel{0};
    for_each_photon_chunk(int64_t{1} << 30, control, [&](int64_t, int64_t first, int64_t last) {
        trace_photon_range(first, last, control, [&](int64_t) {
            if (control.cancelled()) ++traced_after_cancel;
            if (++traced == kCancelAfter) control.cancel();
        });
    });
    EXPECT_GE(traced.load(), kCancelAfter);
    EXPECT_LE(traced_after_cancel.load(),
              int64_t{tbb::info::default_concurrency()} * kPhotonCancelCheck);
}

TEST(PhotonCancel, ACancelledTraceLeavesAnEmptyMap) {
    const Scene scene = parse_scene(R"({"camera": {"position": [0, 5, 5], "look_at": [0, 0, 0]},
        "objects": [{"name": "floor", "type": "sphere", "center": [0, -1001, 0], "radius": 1000,
                     "material": {"color": 0.5}}],
        "lights": [{"type": "point", "position": [0, 1, 0], "power": 100}]})");
    RenderControl control;
    control.cancel();
    PhotonTracingSettings settings;
    settings.photons_per_light = 10000000;
    const PhotonMap map = trace_photons(scene, settings, control);
    EXPECT_EQ(map.direct().size(), 0u);
    EXPECT_EQ(map.caustic().size(), 0u);
}

}  // namespace
}  // namespace lenslab
