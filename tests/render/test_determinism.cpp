// The same seed gives a byte-identical image at 1, 2 and 8 threads, for every integrator
// the registry knows (integrator_names(), so one added later is covered once registered):
// random streams are tied to pixels and photons, never to threads.

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cstring>
#include <string>
#include <vector>

#include "random_scene.h"
#include "render/render_session.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

// The film's bytes: what the image files are written from.
std::vector<unsigned char> bytes_of(const Film& film) {
    std::vector<unsigned char> out(film.pixels().size() * sizeof(PixelRgb));
    std::memcpy(out.data(), film.pixels().data(), out.size());
    return out;
}

std::vector<unsigned char> render_bytes(const Scene& scene, int threads) {
    RenderControl control;
    const RenderResult r = render_scene(scene, control, threads);
    EXPECT_FALSE(r.cancelled);
    return bytes_of(r.film);
}

void expect_same_at_any_thread_count(Scene scene, const std::string& what) {
    for (const std::string& name : integrator_names()) {
        SCOPED_TRACE(what + ", integrator " + name);
        scene.render.integrator = name;
        const std::vector<unsigned char> one = render_bytes(scene, 1);
        EXPECT_EQ(render_bytes(scene, 2), one) << "2 threads differ from 1";
        EXPECT_EQ(render_bytes(scene, 8), one) << "8 threads differ from 1";
    }
}

class Determinism : public ::testing::Test {
protected:
    // Without this TBB caps every arena at the machine's core count, and "8 threads" on a
    // 2-core machine would run on 2.
    tbb::global_control m_threads{tbb::global_control::max_allowed_parallelism, 8};
};

TEST_F(Determinism, DefaultSceneAtOneTwoAndEightThreads) {
    Scene scene = default_scene();
    scene.render.width = 64;
    scene.render.height = 48;
    scene.render.spp = 2;
    scene.render.photons = 30000;
    expect_same_at_any_thread_count(scene, "default scene");
}

TEST_F(Determinism, RandomScenesAtOneTwoAndEightThreads) {
    testing::RandomSceneOptions options;
    options.width = 48;
    options.height = 32;
    options.photons = 20000;
    // Enough passes for the radii to shrink and the averages to mix passes; each pass is
    // split over the threads the same way, so more passes add nothing to check.
    options.passes = 8;
    for (uint64_t seed : {3u, 16u, 19u}) {
        expect_same_at_any_thread_count(testing::random_scene(seed, options),
                                        "random scene " + std::to_string(seed));
    }
}

TEST_F(Determinism, GradientIndexScenesAtOneTwoAndEightThreads) {
    // Curved rays through GRIN solids (the integrator's steps depend on the ray alone).
    for (const char* file : {"luneburg_lens.json", "grin_rod.json"}) {
        Scene scene = load_scene_file(std::string(LENSLAB_SOURCE_DIR) + "/scenes/" + file);
        scene.render.width = 32;
        scene.render.height = 24;
        scene.render.spp = 1;
        scene.render.photons = 5000;
        scene.render.passes = 2;
        scene.render.pass_photons = 2000;
        expect_same_at_any_thread_count(scene, file);
    }
}

}  // namespace
}  // namespace lenslab
