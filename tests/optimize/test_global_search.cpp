// The global search (optimize/global_search.h) on the open lens-design tools' Cooke triplet
// exercise (examples/optimize/cooke.design.json): from three plates, damped least squares
// alone ends in the valley nearest the start; started from many points it finds a lower one,
// and with the example's 128 starts the published result. The starts' region, and the same
// result at one and two threads.

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "analysis/aberrations/polychromatic_spot.h"
#include "analysis/system/first_order.h"
#include "analysis/system/paraxial.h"
#include "optimize/global_search.h"
#include "optimize/local_search.h"
#include "optimize/optimize_design.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

// The exercise with a coarser pupil grid (19 rays a beam) and shorter runs: what the checks
// below need, in a few seconds.
LensDesign cooke() {
    LensDesign d = load_lens_design(LENSLAB_SOURCE_DIR "/examples/optimize/cooke.design.json");
    d.rings = 2;
    d.global_search = {.starts = 12, .start_iterations = 10, .keep = 2, .seed = 1};
    return d;
}

TEST(GlobalSearch, CurvaturesAreDrawnWithinHalfTheirInverseSemiDiameter) {
    const DesignModel model(cooke());
    const std::vector<SearchRange> ranges = search_ranges(model);
    ASSERT_EQ(ranges.size(), 7u);             // six curvatures, the image distance
    EXPECT_DOUBLE_EQ(ranges[0].hi, 0.5 / 9);  // L1: diameter 18
    EXPECT_DOUBLE_EQ(ranges[0].lo, -0.5 / 9);
    EXPECT_DOUBLE_EQ(ranges[2].hi, 0.5 / 6);  // L2: diameter 12
    EXPECT_EQ(ranges[6].lo, ranges[6].hi);    // the image distance is not drawn
    EXPECT_EQ(ranges[6].lo, 40.0);
}

TEST(GlobalSearch, FindsALowerValleyThanTheLocalRunFromTheDesignsStart) {
    const LensDesign design = cooke();
    const DesignModel model(design);
    const int iterations = 60;
    const LmResult local = local_search(model, model.start(), iterations);
    const GlobalSearchResult global = global_search(model, design.global_search, iterations);
    EXPECT_EQ(global.starts.size(), 12u);
    EXPECT_EQ(global.starts[0].x, model.start());  // the design's own start is tried first
    EXPECT_LT(global.solver.merit, 0.5 * local.merit);
    EXPECT_EQ(global.solver.merit, global.starts[global.chosen].polished_merit);
}

// Issue 40's Must-show: the exercise exactly as the example states it (61 rays a beam, 128
// starts) ends at EFL 50.00 ± 0.01 with polychromatic RMS spots at or below the open tool's
// published 0.012 / 0.022 / 0.022 mm and every edge and centre at least 1 mm thick. Checked
// apart from the optimiser's own figures: the written scene read back, the spots with real
// ray aiming on a denser grid (8 rings: 217 rays a wavelength). About 6 s in a release build:
// the sanitized stage skips it (LENSLAB_RELEASE_ONLY_TESTS).
TEST(GlobalSearch, SolvesTheOpenToolsCookeExercise) {
    const LensDesign design =
        load_lens_design(LENSLAB_SOURCE_DIR "/examples/optimize/cooke.design.json");
    const OptimizeResult result = optimize_design(design);
    ASSERT_TRUE(result.global);
    const Scene scene =
        parse_scene(result.scene.dump(), "optimised", design.base_dir, {.require_camera = false});
    const OpticalSystem system = build_optical_system(scene);
    const ParaxialResult paraxial = paraxial_trace(system, kLineD);
    EXPECT_NEAR(paraxial.efl, 50.0, 0.01);
    FirstOrderOptions options;
    options.stop = 3;  // surface 4, counted from 0
    options.epd = 10;
    options.fields = {0, 14, 20};
    const FirstOrder first = first_order(system, paraxial, options);
    const double image_z = system.last_vertex() + result.after.image_distance;
    const double published[] = {0.012, 0.022, 0.022};
    for (size_t f = 0; f < 3; ++f) {
        const PolychromaticSpot spot = polychromatic_rms_spot(
            system, first, options.fields[f], {kLineF, kLineD, kLineC}, {}, 8, image_z);
        EXPECT_LE(spot.rms_radius, published[f]) << options.fields[f] << " degrees";
        EXPECT_EQ(spot.lost, 0);
    }
    for (const SystemElement& e : system.elements) {
        const double centre =
            system.surfaces[e.last_surface].z_at(0) - system.surfaces[e.first_surface].z_at(0);
        const double edge = system.surfaces[e.last_surface].z_at(e.semi_diameter) -
                            system.surfaces[e.first_surface].z_at(e.semi_diameter);
        EXPECT_GE(centre, 1.0);
        EXPECT_GE(edge, 1.0);
    }
}

TEST(GlobalSearch, SameResultAtOneAndTwoThreads) {
    const auto run = [](int threads) {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        LensDesign design = cooke();
        design.global_search.starts = 4;
        design.global_search.start_iterations = 3;  // 6.5 s under ThreadSanitizer with 10
        const DesignModel model(design);
        // Progress comes from the worker threads, one call at a time: the runs count up.
        int calls = 0;
        const auto progress = [&calls](const LmProgress& p) { EXPECT_EQ(p.iteration, ++calls); };
        GlobalSearchResult result = global_search(model, design.global_search, 5, progress);
        int runs = 0;
        for (const GlobalSearchStart& s : result.starts) runs += s.evaluable + s.polished;
        EXPECT_EQ(calls, runs);
        return result;
    };
    const GlobalSearchResult one = run(1), two = run(2);
    EXPECT_EQ(one.chosen, two.chosen);
    EXPECT_EQ(one.solver.x, two.solver.x);  // bit for bit
    EXPECT_EQ(one.solver.merit, two.solver.merit);
    EXPECT_EQ(one.evaluations, two.evaluations);
}

}  // namespace
}  // namespace lenslab
