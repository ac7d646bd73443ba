// `lenslab bench sppm`'s harness: its error measures, and a tiny run.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "bench/sppm_convergence.h"
#include "image/image_io.h"
#include "render/integrator_names.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

Film filled(int w, int h, float v) {
    Film f(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) f.set(x, y, Rgb{v, v, v});
    }
    return f;
}

double luminance_of(const PixelRgb& p) { return p.r + p.g + p.b; }

// A measurement of a few pixels, one pass and no path runs, on one thread.
ConvergenceSettings tiny(int size, int reference_spp) {
    ConvergenceSettings s;
    s.width = s.height = size;
    s.reference_spp = reference_spp;
    s.passes = {1};
    s.path_spp = {};
    s.threads = 1;
    return s;
}

// The caustic room with few photons a pass.
Scene small_caustic_room() {
    Scene scene = load_scene_file(LENSLAB_SOURCE_DIR "/scenes/caustic_room.json");
    scene.render.pass_photons = 500;
    return scene;
}

TEST(SppmConvergence, ErrorsAreRelativeToTheReference) {
    const Film reference = filled(16, 16, 2.0f), off = filled(16, 16, 2.5f);
    EXPECT_DOUBLE_EQ(block_relative_error(reference, reference), 0.0);
    EXPECT_NEAR(block_relative_error(off, reference), 0.25, 1e-6);
    EXPECT_NEAR(rms_relative_error(off, reference), 0.25, 1e-6);
    const int region[4] = {0, 0, 4, 4};
    EXPECT_NEAR(region_relative_error(off, reference, region), 0.25, 1e-6);
}

TEST(SppmConvergence, BlackReferenceBlocksAreSkipped) {
    EXPECT_DOUBLE_EQ(block_relative_error(filled(16, 16, 1.0f), filled(16, 16, 0.0f)), 0.0);
}

TEST(SppmConvergence, RunsSppmAndPathAgainstTheReference) {
    ConvergenceSettings s = tiny(8, 4);
    s.passes = {2, 1};
    s.path_spp = {1};
    const ConvergenceResult r = run_convergence(small_caustic_room(), s, [](const std::string&) {});
    ASSERT_EQ(r.points.size(), 3u);
    EXPECT_EQ(r.points[0].integrator, integrators::kSppm);
    EXPECT_EQ(r.points[0].amount, 1);  // sorted
    EXPECT_EQ(r.points[1].amount, 2);
    EXPECT_EQ(r.points[2].integrator, integrators::kPath);
    EXPECT_EQ(r.reference.width(), 8);
    EXPECT_EQ(r.sppm_last.width(), 8);
    const std::string csv = convergence_csv(r);
    EXPECT_EQ(csv.rfind("integrator,passes_or_spp,seconds,block_error,rms_error,region_error\n", 0),
              0u);
    EXPECT_NE(csv.find("\npath,1,"), std::string::npos) << csv;
}

TEST(SppmConvergence, TheRegionHasAReferenceOfItsOwnAtItsSampleCount) {
    ConvergenceSettings s = tiny(16, 1);
    s.region[0] = 6, s.region[1] = 7, s.region[2] = 10, s.region[3] = 9;  // on the back wall
    s.region_spp = 64;
    const ConvergenceResult r = run_convergence(small_caustic_room(), s, [](const std::string&) {});
    ASSERT_EQ(r.region_reference.width(), 16);
    EXPECT_GT(luminance_of(r.region_reference.at(7, 8)), 0.0);
    EXPECT_EQ(luminance_of(r.region_reference.at(2, 2)), 0.0) << "outside the region";
    // The region's error is measured against its own reference, not the 1-spp whole one.
    ASSERT_EQ(r.points.size(), 1u);
    EXPECT_DOUBLE_EQ(r.points[0].region_error,
                     region_relative_error(r.sppm_last, r.region_reference, s.region));
}

TEST(SppmConvergence, AnEarlierReferenceIsReadNotRendered) {
    ConvergenceSettings s = tiny(8, 4);
    const Scene scene = small_caustic_room();
    const ConvergenceResult first = run_convergence(scene, s, [](const std::string&) {});
    const std::string file =
        (std::filesystem::temp_directory_path() / "lenslab_bench_reference.exr").string();
    write_image(first.reference, file);
    s.reference_file = file;
    const ConvergenceResult again = run_convergence(scene, s, [](const std::string&) {});
    EXPECT_EQ(again.reference_seconds, 0.0);  // not rendered
    ASSERT_EQ(again.points.size(), 1u);
    EXPECT_EQ(again.points[0].block_error, first.points[0].block_error);
    // A reference of another size is refused, saying both sizes.
    s.width = 16;
    try {
        run_convergence(scene, s, [](const std::string&) {});
        ADD_FAILURE() << "a reference of the wrong size was taken";
    } catch (const ImageError& e) {
        EXPECT_NE(std::string(e.what()).find("is 8x8, the measurement 16x8"), std::string::npos)
            << e.what();
    }
    std::filesystem::remove(file);
}

}  // namespace
}  // namespace lenslab
