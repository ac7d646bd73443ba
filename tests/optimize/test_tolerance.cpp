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

// Decentres, tilts and melt errors: one row per lens for each; the Abbe number's tolerance a
// share of the glass's own V_d (HIKARI SK16: SCHOTT's SK16 data sheet gives 60.32; the
// HIKARI equivalent J-SK16's catalogue 60.34).
TEST(Tolerance, DecentresTiltsAndMeltsAreTriedOnEveryLens) {
    LensDesign d = triplet(1);
    d.tolerances = {};
    d.tolerances.decenter = 0.02;
    d.tolerances.tilt = 0.05;
    d.tolerances.index = 0.0005;
    d.tolerances.abbe = 0.8;
    const std::vector<ToleranceItem> items = tolerance_items(d);
    ASSERT_EQ(items.size(), 18u);  // 6 a lens
    EXPECT_EQ(items[0].label, "decentre x L1 ± 0.02");
    EXPECT_EQ(items[3].label, "tilt y L1 ± 0.05°");
    EXPECT_EQ(items[4].label, "n_d L1 ± 0.0005");
    EXPECT_EQ(items[5].label, "V_d L1 ± 0.8%");
    EXPECT_NEAR(items[5].tolerance / 0.008, 60.3, 0.1);
    for (const ToleranceItem& item : items) {
        EXPECT_EQ(item.nominal, 0) << item.label;
        EXPECT_EQ(item.value_at(item.tolerance), item.tolerance) << item.label;
    }
}

// A small decentre of every lens: the refocused RMS spot grows as the decentre's square (its
// coma and the image's tilt are first order in it), so the Monte Carlo's mean change is what
// the table's root-sum-square of the squared criterion's changes predicts for errors uniform
// within ± T (E[e²] = T²/3): 1.5% apart here (the Monte Carlo mean's standard error is 2.8%
// of the change), 1.1% with the example's 61 rays a beam. The root-sum-square of each row's
// worst change (every error at its limit at once, Zemax's estimate) is twice as large.
TEST(Tolerance, ADecentresMonteCarloMeanChangeIsTheTablesRootSumSquare) {
    const int trials = 1000;
    LensDesign d = triplet(trials);
    d.tolerances = {};
    d.tolerances.decenter = 0.05;
    d.tolerances.trials = trials;
    const ToleranceReport r = tolerance_design(d);
    ASSERT_EQ(r.rows.size(), 6u);
    EXPECT_EQ(r.monte_carlo.failed, 0);
    const double predicted = r.predicted_mean - r.nominal;
    const double measured = r.monte_carlo.mean - r.nominal;
    ASSERT_GT(predicted, 0);
    EXPECT_NEAR(measured, predicted, 0.1 * predicted);
    // Decentring along x, across the fields' plane, helps no field: both ends are worse.
    for (const SensitivityRow& row : r.rows) {
        if (row.label.rfind("decentre x", 0) != 0) continue;
        EXPECT_GT(*row.minus, r.nominal) << row.label;
        EXPECT_NEAR(*row.minus, *row.plus, 1e-9) << row.label;
    }
}

// The MTF criterion: the mean over the fields of the MTF at 20 cycles/mm, each made lens
// focused by its RMS spot; its statistics read the other way round (the percentiles are MTFs
// the lenses reach at least). The RMS wavefront criterion: the fields' root mean square.
TEST(Tolerance, TheMtfAndWavefrontCriteria) {
    LensDesign d = triplet(4);
    d.tolerances.radius = d.tolerances.air_gap = 0;  // the three thicknesses alone
    d.tolerances.criterion = "mtf";
    d.tolerances.frequency = 20;
    const ToleranceReport mtf = tolerance_design(d);
    EXPECT_TRUE(mtf.higher_is_better);
    ASSERT_EQ(mtf.nominal_fields.size(), 3u);
    EXPECT_NEAR(mtf.nominal,
                (mtf.nominal_fields[0] + mtf.nominal_fields[1] + mtf.nominal_fields[2]) / 3, 1e-12);
    EXPECT_GT(mtf.nominal, 0);
    EXPECT_LT(mtf.nominal, 1);
    const MonteCarloSummary& m = mtf.monte_carlo;
    EXPECT_LE(m.min, m.max);
    EXPECT_GE(m.p50, m.p90);  // 90% of the lenses reach at least p90
    EXPECT_LE(m.p90, m.max);
    EXPECT_GE(m.p98, m.min);
    // The spot's focus is the RMS spot criterion's own.
    LensDesign spot = d;
    spot.tolerances.criterion = "rms_spot";
    spot.tolerances.trials = 1;
    EXPECT_NEAR(tolerance_design(spot).image_distance, mtf.image_distance, 1e-12);
    d.tolerances.criterion = "rms_wavefront";
    d.tolerances.trials = 1;
    const ToleranceReport w = tolerance_design(d);
    EXPECT_FALSE(w.higher_is_better);
    double sum = 0;
    for (double v : w.nominal_fields) sum += v * v;
    EXPECT_NEAR(w.nominal, std::sqrt(sum / 3), 1e-12);
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
