// The merit function's operands (merit_operand.h, design_evaluation.h) against closed forms:
// - the paraxial EFL of a thick biconvex lens, n = 1.5, R1 = 50, R2 = -50, t = 5, from the
//   lensmaker's equation 1/f = (n - 1) (1/R1 - 1/R2 + (n - 1) t / (n R1 R2)) (Hecht, Optics,
//   5th ed., eq. 6.2): f = 50.847;
// - its edge thickness at the semi-diameter h = 10 from the spherical sag
//   s = R - sqrt(R² - h²): t - 2 s = 5 - 2 (50 - sqrt(2400)) = 2.97959;
// - the total length: first vertex to the image plane;
// - constraints are one-sided, zero while the limit holds; the EFL's residual is the power
//   difference target² (1/target - 1/EFL), EFL - target to first order;
// - its back focal length f (1 - (n - 1) t / (n R1)) (Hecht, eq. 6.3): 49.1525;
// - with the stop on its front face, the entrance pupil is that face (position 0) and the exit
//   pupil its image through the back face: n'/s' - n/s = (n' - n)/R2 with s = -t, n = 1.5,
//   n' = 1 (the single-surface refraction equation, Hecht eq. 5.8), s' = -3.44828 from the
//   last vertex;
// - distortion is the bench's (field_curves.h, checked there against Seidel's S_V), in %;
// - rms_wavefront and mtf are the bench's figures (field_wavefront.h, field_mtf.h) at the
//   optimiser's fixed sampling, and an image_distance freed against rms_wavefront settles at
//   the least-RMS focus of pupil_from_rays.h, midway between the paraxial and marginal foci
//   for primary spherical aberration (Mahajan, Optical Imaging and Aberrations, part I, 8.3).

#include <gtest/gtest.h>

#include <cmath>

#include "analysis/aberrations/field_curves.h"
#include "analysis/diffraction/field_mtf.h"
#include "analysis/diffraction/pupil_from_rays.h"
#include "analysis/diffraction/zernike.h"
#include "analysis/system/paraxial.h"
#include "optimize/design_evaluation.h"
#include "optimize/optimize_design.h"
#include "optimize_test_design.h"
#include "scene/scene_json.h"
#include "util/scene_error.h"

namespace lenslab {
namespace {

using test::design_of;
using test::sphere;

const std::vector<test::LensSpec> kBiconvex = {{"B", 0.0, 5.0, 20.0, sphere(50), sphere(-50)}};

// A design's system as the bench builds it, and its first-order data as design_of sets it up
// (the d line, the stop on surface 1, EPD 4, the design's fields): what the operands are
// checked against.
struct Bench {
    OpticalSystem system;
    FirstOrder first;
};

Bench bench_of(const LensDesign& d) {
    Bench b;
    b.system = build_optical_system(
        scene_from_json(nlohmann::json(d.scene), d.base_dir, {.require_camera = false}));
    FirstOrderOptions f;
    f.wavelength_nm = 587.5618;
    f.stop = 0;
    f.epd = 4;
    f.fields = d.fields;
    b.first = first_order(b.system, paraxial_trace(b.system, f.wavelength_nm), f);
    return b;
}

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

TEST(MeritOperand, BackFocalLengthAndDistortion) {
    const nlohmann::json operands = {{{"type", "bfl"}, {"target", 49}},
                                     {{"type", "distortion"}, {"field", 5}},
                                     {{"type", "distortion"}}};
    const LensDesign d = lens_design_from_json(
        design_of(kBiconvex, {{"fields", {0, 5}}, {"operands", operands}, {"image_distance", 48}}),
        "");
    ASSERT_EQ(d.operands.size(), 3u);  // the last distortion: only the field off the axis
    EXPECT_EQ(operand_label(d.operands[2]), "distortion 5°");
    const std::optional<DesignEvaluation> e = DesignModel(d).evaluate({});
    ASSERT_TRUE(e);
    const double n = 1.5, r1 = 50, r2 = -50, t = 5;
    const double efl = 1 / ((n - 1) * (1 / r1 - 1 / r2 + (n - 1) * t / (n * r1 * r2)));
    EXPECT_NEAR(e->values[0], efl * (1 - (n - 1) * t / (n * r1)), 1e-9);
    EXPECT_NEAR(e->residuals[0], e->values[0] - 49, 1e-12);

    const Bench b = bench_of(d);
    const OpticalSystem& system = b.system;
    const FirstOrder& first = b.first;
    FieldCurveOptions c;
    c.max_field = 5;
    c.points = 2;
    c.wavelengths = {587.5618};
    c.image_z = system.last_vertex() + 48;
    const double bench = field_curves(system, first, c).curves[0].points.back().distortion;
    EXPECT_NEAR(e->values[1], 100 * bench, 1e-12);
    EXPECT_EQ(e->values[2], e->values[1]);
    EXPECT_NE(e->values[1], 0.0);

    const nlohmann::json on_axis = {{{"type", "distortion"}, {"field", 0}}};
    try {
        lens_design_from_json(design_of(kBiconvex, {{"operands", on_axis}}), "");
        FAIL() << "distortion on the axis accepted";
    } catch (const SceneError& err) {
        EXPECT_EQ(err.path(), "operands[0].field");
    }
}

TEST(MeritOperand, PupilPositions) {
    const nlohmann::json operands = {{{"type", "entrance_pupil_position"}, {"target", 1}},
                                     {{"type", "exit_pupil_position"}, {"target", -3}}};
    const LensDesign d = lens_design_from_json(design_of(kBiconvex, {{"operands", operands}}), "");
    const std::optional<DesignEvaluation> e = DesignModel(d).evaluate({});
    ASSERT_TRUE(e);
    const double n = 1.5, r2 = -50, t = 5;
    const double exit = 1 / ((1 - n) / r2 + n / -t);  // n' = 1
    EXPECT_NEAR(e->values[0], 0.0, 1e-12);
    EXPECT_NEAR(e->values[1], exit, 1e-9);
    EXPECT_NEAR(exit, -3.448275862, 1e-9);
    EXPECT_NEAR(e->residuals[0], -1.0, 1e-12);
    EXPECT_NEAR(e->residuals[1], exit + 3, 1e-9);
}

TEST(MeritOperand, WavefrontAndMtfAreTheBenchsFigures) {
    const nlohmann::json operands = {
        {{"type", "rms_wavefront"}, {"field", 2}},
        {{"type", "mtf"}, {"field", 2}, {"frequency", 40}, {"direction", "tangential"}},
        {{"type", "mtf"}, {"frequency", 40}}};
    const LensDesign d = lens_design_from_json(
        design_of(kBiconvex, {{"fields", {0, 2}}, {"operands", operands}, {"image_distance", 48}}),
        "");
    ASSERT_EQ(d.operands.size(), 4u);  // the last mtf: one per field
    EXPECT_EQ(operand_label(d.operands[1]), "mtf 40 T 2°");
    EXPECT_EQ(operand_label(d.operands[3]), "mtf 40 T+S 2°");
    EXPECT_EQ(d.operands[1].target, 1.0);
    const std::optional<DesignEvaluation> e = DesignModel(d).evaluate({});
    ASSERT_TRUE(e);

    const Bench b = bench_of(d);
    const OpticalSystem& system = b.system;
    const FirstOrder& first = b.first;
    FieldWavefrontOptions w;
    w.field = 2;
    w.wavelength_nm = 587.5618;
    w.sampling = {32, 2};
    w.image_z = system.last_vertex() + 48;
    const FieldWavefront wavefront = field_wavefront(system, first, w);
    EXPECT_NEAR(e->values[0], fit_zernike(wavefront.pupil, ZernikeOrdering::Noll, 3).residual_rms,
                1e-12);
    EXPECT_GT(e->values[0], 0.1);  // a singlet 3 mm out of focus
    FieldMtfOptions m;
    m.fields = {2};
    m.frequencies = {40};
    m.samples = 32;
    m.resolve = false;
    m.image_z = *w.image_z;
    const FieldMtfs mtf = field_mtfs(system, first, m);
    EXPECT_NEAR(e->values[1], mtf.fields[0].tangential[0], 1e-12);
    EXPECT_NEAR(e->values[3], 0.5 * (mtf.fields[0].tangential[0] + mtf.fields[0].sagittal[0]),
                1e-12);
    EXPECT_NEAR(e->residuals[1], e->values[1] - 1.0, 1e-12);
}

TEST(MeritOperand, MtfNeedsAFrequencyAndOthersTakeNone) {
    const auto error_of = [](const nlohmann::json& op) {
        try {
            lens_design_from_json(design_of(kBiconvex, {{"operands", {op}}}), "");
        } catch (const SceneError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(error_of({{"type", "mtf"}}).find("operands[0]"), std::string::npos);
    EXPECT_NE(error_of({{"type", "mtf"}, {"frequency", -3}}).find("must be > 0"),
              std::string::npos);
    EXPECT_NE(error_of({{"type", "mtf"}, {"frequency", 3}, {"direction", "diagonal"}}),
              std::string());
    EXPECT_NE(error_of({{"type", "rms_spot"}, {"frequency", 3}})
                  .find("an rms_spot operand takes no frequency (it takes field, target, weight)"),
              std::string::npos);
}

TEST(MeritOperand, FreeingTheImagePlaneAgainstTheWavefrontFindsTheLeastRmsFocus) {
    // A biconvex singlet at F/5 (EPD 10): strong primary spherical aberration.
    const std::vector<test::LensSpec> singlet = {{"B", 0.0, 5.0, 20.0, sphere(50), sphere(-50)}};
    const LensDesign d = lens_design_from_json(
        design_of(singlet, {{"epd", 10},
                            {"image_distance", 48},
                            {"variables", {{{"type", "image_distance"}}}},
                            {"operands", {{{"type", "rms_wavefront"}, {"field", 0}}}}}),
        "");
    const OptimizeResult result = optimize_design(d, 50);
    const double found = result.after.image_distance;

    const Scene scene =
        scene_from_json(nlohmann::json(d.scene), d.base_dir, {.require_camera = false});
    const OpticalSystem system = build_optical_system(scene);
    RayPupilOptions axial;
    axial.wavelength_nm = 587.5618;
    axial.aperture_radius = 5;
    const RayWavefront reference(system, axial);
    const double best = reference.best_focus_z() - system.last_vertex();
    const double paraxial = reference.paraxial_focus_z() - system.last_vertex();
    EXPECT_GT(paraxial - best, 0.2);  // the least-RMS focus well inside the paraxial one
    EXPECT_NEAR(found, best, 0.02 * (paraxial - best));
}

}  // namespace
}  // namespace lenslab
