// The global search (optimize/global_search.h) on the open lens-design tools' Cooke triplet
// exercise (examples/optimize/cooke.design.json): from three plates, damped least squares
// alone ends in the valley nearest the start; started from many points it finds a lower one.
// The starts' region, and the same result at one and two threads.

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "optimize/global_search.h"
#include "optimize/local_search.h"

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

TEST(GlobalSearch, SameResultAtOneAndTwoThreads) {
    const auto run = [](int threads) {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        LensDesign design = cooke();
        design.global_search.starts = 4;
        const DesignModel model(design);
        return global_search(model, design.global_search, 5);
    };
    const GlobalSearchResult one = run(1), two = run(2);
    EXPECT_EQ(one.chosen, two.chosen);
    EXPECT_EQ(one.solver.x, two.solver.x);  // bit for bit
    EXPECT_EQ(one.solver.merit, two.solver.merit);
    EXPECT_EQ(one.evaluations, two.evaluations);
}

}  // namespace
}  // namespace lenslab
