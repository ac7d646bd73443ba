// Tolerancing (optimize/tolerance.h) of the optimised Cooke triplet of
// examples/optimize/triplet.tolerance.json: the tolerances found on every lens, a radius error
// applied to the radius (not the curvature), the Monte Carlo's spread and mean against what the
// sensitivity table predicts for errors uniform within their tolerance (first order:
// sd = √(Σ ((plus - minus) / 2)² / 3); second order for the mean), and the same report at one
// and two threads.

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>

#include "optimize/tolerance.h"
#include "optimize/tolerance_figure.h"

namespace lenslab {
namespace {

LensDesign triplet(int trials) {
    LensDesign d = load_lens_design(LENSLAB_SOURCE_DIR "/examples/optimize/triplet.tolerance.json");
    d.rings = 2;  // 19 rays a beam: the checks below hold as well, in a third of the time
    d.tolerances.trials = trials;
    return d;
}

TEST(Tolerance, EveryCurvedFaceThicknessAndAirGapIsTolerated) {
    const std::vector<ToleranceItem> items = tolerance_items(triplet(1));
    ASSERT_EQ(items.size(), 11u);  // 6 radii, 3 thicknesses, 2 air gaps
    EXPECT_EQ(items[0].label, "radius L1.front ± 0.05");
    EXPECT_EQ(items[3].label, "air gap after L1 ± 0.05");
    for (const ToleranceItem& item : items) {
        if (item.variable.kind != VariableKind::Curvature) {
            EXPECT_NEAR(item.value_at(0.05) - item.nominal, 0.05, 1e-12) << item.label;
            continue;
        }
        // The radius made 0.05 longer, the curvature following.
        EXPECT_NEAR(1 / item.value_at(0.05) - 1 / item.nominal, 0.05, 1e-9) << item.label;
    }
}

TEST(Tolerance, TheMonteCarloSpreadIsWhatTheSensitivityTablePredicts) {
    const int trials = 300;
    const ToleranceReport r = tolerance_design(triplet(trials));
    const MonteCarloSummary& m = r.monte_carlo;
    EXPECT_EQ(m.failed, 0);
    ASSERT_EQ(m.criteria.size(), size_t(trials));
    // Measured 3.6% apart (1000 trials, 61 rays a beam); the estimate's own error is about
    // 1 / √(2 N) = 4%.
    EXPECT_NEAR(m.sd, r.predicted_sd, 0.1 * r.predicted_sd);
    EXPECT_NEAR(m.mean, r.predicted_mean, 3 * m.sd / std::sqrt(double(trials)));
    // Refocusing: no made lens is worse than the table's worst single error by much more
    // than all of them together.
    EXPECT_LT(m.max, r.nominal + 3 * r.rss_change);
    EXPECT_LE(m.p50, m.p90);
    EXPECT_LE(m.p90, m.p98);
}

TEST(Tolerance, SameReportAtOneAndTwoThreads) {
    const auto run = [](int threads) {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                                        size_t(threads));
        return tolerance_design(triplet(12));
    };
    const ToleranceReport one = run(1), two = run(2);
    EXPECT_EQ(one.monte_carlo.criteria, two.monte_carlo.criteria);
    ASSERT_EQ(one.rows.size(), two.rows.size());
    for (size_t i = 0; i < one.rows.size(); ++i) {
        EXPECT_EQ(one.rows[i].minus, two.rows[i].minus);
        EXPECT_EQ(one.rows[i].plus, two.rows[i].plus);
    }
}

TEST(Tolerance, RefocusingFindsAPlaneAtLeastAsGood) {
    LensDesign fixed = triplet(4);
    fixed.tolerances.refocus = false;
    const ToleranceReport still = tolerance_design(fixed);
    const ToleranceReport refocused = tolerance_design(triplet(4));
    EXPECT_LE(refocused.nominal, still.nominal);
    EXPECT_NEAR(still.image_distance, 40.27, 1e-12);  // the design's plane, kept
}

// The figure: the histogram holds every evaluated lens, the yield ends at the share that
// could be evaluated, the nominal is marked; its title counts the lenses.
TEST(Tolerance, TheFigureCountsEveryMadeLens) {
    ToleranceReport r;
    r.nominal = 0.02;
    r.monte_carlo.trials = 5;
    r.monte_carlo.failed = 1;
    r.monte_carlo.criteria = {0.021, 0.019, 0.025, 0.022};
    const RayDiagram d = tolerance_figure(r, "mm");
    EXPECT_EQ(d.title, "Monte Carlo of 5 made lenses (1 could not be evaluated)");
    EXPECT_NE(d.subtitle.find("0.02 mm"), std::string::npos) << d.subtitle;
    // Two panels of two curves each (the data and the nominal's dashed line), in the
    // diagram's coordinates: the yield's last point 0.8 of its panel's height (-1 to 1).
    std::vector<const DiagramPath*> curves;
    for (const DiagramPath& p : d.paths) {
        if (p.points.size() >= 2 && !p.closed) curves.push_back(&p);
    }
    ASSERT_GE(curves.size(), 4u);
    const DiagramPath& yield = *curves[curves.size() - 2];
    EXPECT_NEAR(yield.points.back().y, -1 + 2 * 0.8, 1e-9);
}

}  // namespace
}  // namespace lenslab
