// The Python module's background renders (render/background_work.h), without Python: a render
// on its own thread while this one polls its progress, cancelled by destruction part-way, and
// an exception handed back. test_threaded runs these under ThreadSanitizer (stage 3), which
// checks the progress hand-over, the cancel and the result for races; the interpreter itself
// is not instrumented (docs/reliability.md).

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "render/background_work.h"
#include "render/render_session.h"
#include "scene/scene_json.h"

using namespace lenslab;
using namespace std::chrono_literals;

TEST(BackgroundWork, ARenderRunsToTheEndWhileThePollerReadsItsProgress) {
    Scene scene = default_scene();
    scene.render.integrator = "whitted";  // no photon pass: seconds under ThreadSanitizer
    scene.render.width = 48;
    scene.render.height = 32;
    scene.render.spp = 2;
    BackgroundWork<RenderResult> work(
        [&scene](RenderControl& control) { return render_scene(scene, control, 2); });
    double last = -1;
    while (!work.wait_for(1ms)) {
        const double fraction = work.progress();
        EXPECT_GE(fraction, last);  // never goes back
        last = fraction;
    }
    const RenderResult result = work.get();
    EXPECT_FALSE(result.cancelled);
    EXPECT_EQ(result.film.width(), 48);
    EXPECT_DOUBLE_EQ(work.progress(), 1.0);
}

TEST(BackgroundWork, DestroyedPartWayItCancelsTheRenderAndWaitsForIt) {
    Scene scene = default_scene();
    scene.render.integrator = "whitted";
    scene.render.width = 640;
    scene.render.height = 480;
    scene.render.spp = 64;  // far more than the test waits for
    std::atomic<bool> cancelled{false};
    {
        BackgroundWork<RenderResult> work([&](RenderControl& control) {
            RenderResult r = render_scene(scene, control, 2);
            cancelled = r.cancelled;
            return r;
        });
        while (work.progress() <= 0) std::this_thread::sleep_for(1ms);  // a tile is done
    }  // the destructor cancels and waits: the work has ended here
    EXPECT_TRUE(cancelled.load());
}

TEST(BackgroundWork, TheWorksExceptionComesBackToThePoller) {
    BackgroundWork<int> work([](RenderControl&) -> int { throw std::runtime_error("no scene"); });
    while (!work.wait_for(1ms)) {
    }
    EXPECT_THROW(work.get(), std::runtime_error);
}
