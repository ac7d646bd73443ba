// The merit function's operands (merit_operand.h, design_evaluation.h) against closed forms:
// - the paraxial EFL of a thick biconvex lens, n = 1.5, R1 = 50, R2 = -50, t = 5, from the
//   lensmaker's equation 1/f = (n - 1) (1/R1 - 1/R2 + (n - 1) t / (n R1 R2)) (Hecht, Optics,
//   5th ed., eq. 6.2): f = 50.847;
// - its edge thickness at the semi-diameter h = 10 from the spherical sag
//   s = R - sqrt(R² - h²): t - 2 s = 5 - 2 (50 - sqrt(2400)) = 2.97959;
// - the total length: first vertex to the image plane;
// - constraints are one-sided, zero while the limit holds; the EFL's residual is the power
//   difference target² (1/target - 1/EFL), EFL - target to first order.

#include <gtest/gtest.h>

#include <cmath>

#include "optimize/design_evaluation.h"
#include "optimize_test_design.h"

namespace lenslab {
namespace {

using test::design_of;
using test::sphere;

const std::vector<test::LensSpec> kBiconvex = {{"B", 0.0, 5.0, 20.0, sphere(50), sphere(-50)}};

TEST(MeritOperand, ThickLensFiguresMatchTheirFormulas) {
    const nlohmann::json operands = {
        {{"type", "efl"}, {"target", 50}},
        {{"type", "min_edge_thickness"}, {"lens", "B"}, {"limit", 4}},
        {{"type", "max_center_thickness"}, {"lens", "B"}, {"limit", 4}},
        {{"type", "min_center_thickness"}, {"lens", "B"}, {"limit", 4}},
        {{"type", "max_total_length"}, {"limit", 100}}};
    const LensDesign d = lens_design_from_json(
        design_of(kBiconvex, {{"operands", operands}, {"image_distance", 45}}), "");
    const DesignModel model(d);
    const std::optional<DesignEvaluation> e = model.evaluate({});
    ASSERT_TRUE(e);
    const double n = 1.5, r1 = 50, r2 = -50, t = 5;
    const double efl = 1 / ((n - 1) * (1 / r1 - 1 / r2 + (n - 1) * t / (n * r1 * r2)));
    EXPECT_NEAR(e->values[0], efl, 1e-9);
    EXPECT_NEAR(e->values[1], 5 - 2 * (50 - std::sqrt(2400.0)), 1e-9);
    EXPECT_NEAR(e->values[2], 5.0, 1e-12);
    EXPECT_NEAR(e->values[4], 50.0, 1e-12);  // last vertex at 5, the image 45 behind
    // Residuals: EFL in power, the edge limit 4 broken by 1.02, the centre 5 > 4, the
    // minimum 4 and the length held.
    EXPECT_NEAR(e->residuals[0], 50 * 50 * (1 / 50.0 - 1 / efl), 1e-9);
    EXPECT_NEAR(e->residuals[1], 4 - e->values[1], 1e-9);
    EXPECT_NEAR(e->residuals[2], 1.0, 1e-12);
    EXPECT_EQ(e->residuals[3], 0.0);
    EXPECT_EQ(e->residuals[4], 0.0);
}

TEST(MeritOperand, WeightsScaleTheMerit) {
    const LensDesign d = lens_design_from_json(
        design_of(
            kBiconvex,
            {{"operands",
              {{{"type", "max_center_thickness"}, {"lens", "B"}, {"limit", 3}, {"weight", 4}}}}}),
        "");
    const std::optional<DesignEvaluation> e = DesignModel(d).evaluate({});
    ASSERT_TRUE(e);
    EXPECT_NEAR(e->merit, 4 * 2.0 * 2.0, 1e-12);  // weight * (5 - 3)²
}

TEST(MeritOperand, RmsSpotWithoutAFieldStandsForEveryField) {
    const LensDesign d = lens_design_from_json(
        design_of(kBiconvex, {{"fields", {0, 2, 4}}, {"operands", {{{"type", "rms_spot"}}}}}), "");
    ASSERT_EQ(d.operands.size(), 3u);
    EXPECT_EQ(d.operands[2].field, 4.0);
    EXPECT_EQ(operand_label(d.operands[1]), "rms_spot 2°");
}

}  // namespace
}  // namespace lenslab
