// The MTF at any field, polychromatic (analysis/diffraction/field_mtf.h):
// - a perfect F/5 mirror (a paraboloid on its axis) defocused by a quarter wave (W020 =
//   δz/(8N²)) has Hopkins' defocused MTF (Hopkins, Proc. R. Soc. A 231, 91 (1955)): the
//   autocorrelation of the defocused pupil, (1/π) ∫ 2√(1 − (|x| + s)²) cos(8π W020 s x) dx
//   over |x| ≤ 1 − s at s = ν/ν_c, integrated here independently of the FFT, within 0.005 at
//   five frequencies;
// - through focus, planes ±1/8 to ±1/2 wave of defocus give Hopkins' MTF at each;
// - a mirror has no colour: at two wavelengths, weighted 1 and 3, its MTF is the weighted
//   diffraction limit;
// - a PSF moved by a tilt is the tilt-free one shifted by 2 t λN: untilted_psf's OTF times
//   exp(−i2π ν·shift) is the tilted pupil's own OTF by FFT (the shift theorem, its sign
//   included), to 1e-6;
// - ten waves of defocus: the sampling is raised until the pupil's phase steps are a quarter
//   wave, and the MTF is still Hopkins' (within 0.01, down to 0.005 of the cutoff, where the
//   OTF falls within a few of its FFT samples);
// - off the axis the tangential and sagittal MTF of a mirror with coma differ, and a field
//   whose chief ray does not pass is reported as such.

#include <gtest/gtest.h>

#include <cmath>

#include "analysis/diffraction/field_mtf.h"
#include "math/constants.h"
#include "paraboloid_bench.h"

namespace lenslab {
namespace {

constexpr double kMtfMirrorFocal = 500.0, kMtfMirrorDiameter = 100.0;  // F/5

OpticalSystem mtf_mirror_system() {
    return test::paraboloid_mirror(kMtfMirrorFocal, kMtfMirrorDiameter);
}

FirstOrder mtf_first_order(const OpticalSystem& system, double field) {
    return test::mirror_first_order(system, kMtfMirrorDiameter, field);
}

// Hopkins' defocused OTF by Simpson's rule over the overlap of the two pupils.
double hopkins_defocused_mtf(double s, double w020) {
    if (s >= 1) return 0;
    const int n = 20000;  // even
    const double a = -(1 - s), h = 2 * (1 - s) / n;
    double sum = 0;
    for (int k = 0; k <= n; ++k) {
        const double x = a + k * h;
        const double chord = 1 - (std::abs(x) + s) * (std::abs(x) + s);
        const double f = 2 * std::sqrt(std::max(0.0, chord)) * std::cos(8 * kPi * w020 * s * x);
        sum += f * (k == 0 || k == n ? 1 : (k % 2 ? 4 : 2));
    }
    return std::abs(sum * h / 3 / kPi);
}

TEST(FieldMtf, AQuarterWaveOfDefocusGivesHopkinsMtf) {
    const OpticalSystem system = mtf_mirror_system();
    const FirstOrder f = mtf_first_order(system, 0);
    const double n = kMtfMirrorFocal / kMtfMirrorDiameter, lambda = kLineD * 1e-6;
    const double cutoff = 1 / (lambda * n);
    FieldMtfOptions o;
    o.image_z = -kMtfMirrorFocal + 0.25 * lambda * 8 * n * n;  // W020 = δz / (8 N²)
    o.samples = 128;
    for (double s : {0.05, 0.1, 0.2, 0.4, 0.7}) o.frequencies.push_back(s * cutoff);
    const FieldMtfs m = field_mtfs(system, f, o);
    ASSERT_EQ(m.fields.size(), 1u);
    ASSERT_TRUE(m.fields[0].error.empty());
    for (size_t k = 0; k < o.frequencies.size(); ++k) {
        const double s = o.frequencies[k] / cutoff;
        const double expected = hopkins_defocused_mtf(s, 0.25);
        EXPECT_NEAR(m.fields[0].tangential[k], expected, 0.005) << "s = " << s;
        EXPECT_NEAR(m.fields[0].sagittal[k], expected, 0.005) << "s = " << s;
        EXPECT_LT(expected, diffraction_limited_mtf(o.frequencies[k], cutoff) - 0.01);
    }
}

TEST(FieldMtf, ThroughFocusFollowsHopkinsDefocus) {
    // At 0.2 of the cutoff, planes ±1/8, ±1/4 and ±1/2 wave of defocus (W020 = δz / (8N²))
    // either side of the focus: symmetric, highest at the focus, Hopkins' value at each.
    const OpticalSystem system = mtf_mirror_system();
    const FirstOrder f = mtf_first_order(system, 0);
    const double n = kMtfMirrorFocal / kMtfMirrorDiameter, lambda = kLineD * 1e-6;
    const double cutoff = 1 / (lambda * n), wave = lambda * 8 * n * n;
    FieldMtfOptions o;
    o.image_z = -kMtfMirrorFocal;
    o.samples = 128;
    const std::vector<double> waves{-0.5, -0.25, -0.125, 0, 0.125, 0.25, 0.5};
    std::vector<double> shifts;
    for (double w : waves) shifts.push_back(w * wave);
    const ThroughFocusMtf t = through_focus_mtf(system, f, o, 0.2 * cutoff, shifts);
    ASSERT_EQ(t.fields.size(), 1u);
    const FieldMtf& axis = t.fields[0];
    ASSERT_EQ(axis.tangential.size(), waves.size());
    for (size_t k = 0; k < waves.size(); ++k) {
        EXPECT_NEAR(axis.tangential[k], hopkins_defocused_mtf(0.2, std::abs(waves[k])), 0.005)
            << waves[k];
        EXPECT_NEAR(axis.sagittal[k], axis.tangential[k], 1e-6);
        EXPECT_LE(axis.tangential[k], axis.tangential[3] + 1e-9);
    }
}

TEST(FieldMtf, TenWavesOfDefocusRaiseTheSamplingAndStillGiveHopkinsMtf) {
    // 64 samples across would step 2·10·(2/64) ≈ 0.6 waves at the rim: aliased. The sampling
    // is raised until the steps are a quarter wave.
    const OpticalSystem system = mtf_mirror_system();
    const FirstOrder f = mtf_first_order(system, 0);
    const double n = kMtfMirrorFocal / kMtfMirrorDiameter, lambda = kLineD * 1e-6;
    const double cutoff = 1 / (lambda * n);
    FieldMtfOptions o;
    o.image_z = -kMtfMirrorFocal - 10 * lambda * 8 * n * n;
    for (double s : {0.005, 0.01, 0.02, 0.05, 0.1}) o.frequencies.push_back(s * cutoff);
    const FieldMtfs m = field_mtfs(system, f, o);
    const FieldMtf& axis = m.fields[0];
    EXPECT_GE(axis.samples, 150);  // 64 · 0.6 / 0.25
    EXPECT_LE(axis.max_step_waves, 0.3);
    EXPECT_TRUE(axis.warning.empty());
    for (size_t k = 0; k < o.frequencies.size(); ++k) {
        const double s = o.frequencies[k] / cutoff;
        EXPECT_NEAR(axis.tangential[k], hopkins_defocused_mtf(s, 10), 0.01) << "s = " << s;
    }
}

TEST(FieldMtf, AMirrorsPolychromaticMtfIsTheWeightedDiffractionLimit) {
    const OpticalSystem system = mtf_mirror_system();
    const FirstOrder f = mtf_first_order(system, 0);
    FieldMtfOptions o;
    o.image_z = -kMtfMirrorFocal;
    o.wavelengths = {486.1327, 656.2725};
    o.weights = {1, 3};
    o.frequencies = {50, 100, 200, 300};
    const FieldMtfs m = field_mtfs(system, f, o);
    for (size_t k = 0; k < o.frequencies.size(); ++k) {
        const double limit =
            (diffraction_limited_mtf(o.frequencies[k], 1 / (486.1327e-6 * 5)) +
             3 * diffraction_limited_mtf(o.frequencies[k], 1 / (656.2725e-6 * 5))) /
            4;
        EXPECT_NEAR(m.diffraction_limit[k], limit, 1e-12);
        EXPECT_NEAR(m.fields[0].tangential[k], limit, 0.005) << o.frequencies[k];
        EXPECT_NEAR(m.fields[0].sagittal[k], limit, 0.005) << o.frequencies[k];
    }
}

TEST(FieldMtf, ATiltShiftsThePsfAsTheShiftTheoremSays) {
    // Coma (an asymmetric PSF, a complex OTF) plus a tilt of half a wave in y: the PSF moves
    // by 2 · 0.5 · λN = λN, two samples of the padded grid.
    const auto wavefront = [](double x, double y) { return 0.3 * (x * x + y * y) * y + 0.5 * y; };
    const PupilFunction tilted = make_pupil({64, 2}, 1e-3, 5, wavefront);
    const UntiltedPsf untilted = untilted_psf(tilted);
    EXPECT_NEAR(untilted.shift_x, 0, 1e-12);
    // The fit takes coma's own tilt (ρ³ sin θ holds 2/3 ρ sin θ at its Z7 balance) too.
    EXPECT_GT(untilted.shift_y, 1e-3 * 5);
    // The tilted pupil's own OTF, by FFT, at its grid frequencies (no interpolation there).
    const OpticalTransfer direct = compute_otf(compute_psf(tilted));
    for (int k : {3, 10, 25, 50}) {
        const double nu = k * direct.spacing;
        const std::complex<double> moved_y =
            untilted.otf_along_y(nu) * std::polar(1.0, -2 * kPi * nu * untilted.shift_y);
        EXPECT_NEAR(std::abs(moved_y - direct.value(0, nu)), 0, 1e-6) << k;
        EXPECT_NEAR(std::abs(untilted.otf_along_x(nu) - direct.value(nu, 0)), 0, 1e-6) << k;
    }
}

TEST(FieldMtf, OffTheAxisTangentialAndSagittalDiffer) {
    const OpticalSystem system = mtf_mirror_system();
    const double degrees = 1.0;
    const FirstOrder f = mtf_first_order(system, degrees);
    FieldMtfOptions o;
    o.fields = {0, degrees, 89};
    o.image_z = -kMtfMirrorFocal;
    o.frequencies = {100, 200};
    const FieldMtfs m = field_mtfs(system, f, o);
    ASSERT_EQ(m.fields.size(), 3u);
    const FieldMtf& off = m.fields[1];
    ASSERT_TRUE(off.error.empty());
    EXPECT_GT(std::abs(off.tangential[1] - off.sagittal[1]), 0.02);
    EXPECT_LT(off.tangential[1], m.fields[0].tangential[1]);
    EXPECT_FALSE(m.fields[2].error.empty());
    EXPECT_TRUE(m.fields[2].tangential.empty());
}

}  // namespace
}  // namespace lenslab
