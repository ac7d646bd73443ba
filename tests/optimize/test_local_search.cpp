// Bounded variables (optimize/local_search.h): MINUIT's sine transform maps the solver's
// unbounded u onto [min, max] and back, and an optimisation whose free optimum lies outside a
// bound ends inside it, at the bound.

#include <gtest/gtest.h>

#include <cmath>

#include "optimize/local_search.h"

namespace lenslab {
namespace {

const std::string kBoundedDesign =
    std::string(LENSLAB_TEST_DATA) + "/optimize/data/triplet_near.design.json";

DesignVariable bounded(double lo, double hi) {
    DesignVariable v;
    v.kind = VariableKind::Thickness;
    v.min = lo;
    v.max = hi;
    return v;
}

TEST(LocalSearch, TheSineTransformMapsOntoTheBoundsAndBack) {
    const DesignVariable v = bounded(2, 6);
    for (double x : {2.0, 2.5, 4.0, 5.999, 6.0}) {
        EXPECT_NEAR(bounded_from_internal(v, internal_from_bounded(v, x)), x, 1e-12) << x;
    }
    for (double u : {-100.0, -1.0, 0.0, 0.7, 3.0, 1e6}) {
        const double x = bounded_from_internal(v, u);
        EXPECT_GE(x, 2.0) << u;
        EXPECT_LE(x, 6.0) << u;
    }
    EXPECT_DOUBLE_EQ(bounded_from_internal(v, 0), 4.0);  // u = 0: the middle
    DesignVariable free;
    EXPECT_EQ(bounded_from_internal(free, 7.25), 7.25);  // no bounds: u is x
    EXPECT_EQ(internal_from_bounded(free, 7.25), 7.25);
}

TEST(LocalSearch, ABoundedVariableEndsWithinItsBounds) {
    LensDesign design = load_lens_design(kBoundedDesign);
    design.rings = 2;
    // The image distance pinned near its start (40.3): the free run moves it by more.
    DesignVariable& image = design.variables.back();
    ASSERT_EQ(image.kind, VariableKind::ImageDistance);
    const DesignModel free_model(design);
    const LmResult free_run = local_search(free_model, free_model.start(), 8);
    const double moved = free_run.x.back() - 40.3;
    ASSERT_GT(std::abs(moved), 0.002) << "the free run should move the image plane";
    image.min = 40.3 - 0.0005;
    image.max = 40.3 + 0.0005;
    const DesignModel model(design);
    const LmResult run = local_search(model, model.start(), 8);
    EXPECT_GE(run.x.back(), 40.3 - 0.0005);
    EXPECT_LE(run.x.back(), 40.3 + 0.0005);
    EXPECT_LT(run.merit, model.evaluate(model.start())->merit);  // it still improves
}

}  // namespace
}  // namespace lenslab
