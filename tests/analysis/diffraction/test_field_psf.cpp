// The matrix-transform PSF (analysis/diffraction/matrix_psf.h) and the polychromatic PSF at
// every field (field_psf.h):
// - on the FFT's own grid the matrix transform gives the FFT PSF (diffraction.h) to 1e-9, and
//   a grid moved onto a tilted pupil's image finds its peak there (x = 2tλN);
// - a perfect F/10 mirror: polychromatic Strehl 1 at two wavelengths (a mirror has no
//   colour), and the encircled energy of the Airy pattern, Rayleigh's 1 − J0²(v) − J1²(v) with
//   v = π r/(λN) (Born & Wolf, Principles of Optics, section 8.5.2), within 0.005 at every
//   radius, the light beyond the grid counted as outside (Parseval);
// - off the axis the polychromatic Strehl of one wavelength is that wavelength's Huygens
//   Strehl within 1%, and the PSF's centroid lies off the chief ray's image point on the side
//   of the coma's flare;
// - a field no ray reaches gets its error, the others their PSFs;
// - by Huygens' wavelets (PsfMethod::Huygens) the polychromatic PSF is the transform's, sample
//   by sample within 1% of the peak (two wavelengths, their grids shifted off the reference).

#include <gtest/gtest.h>

#include <cmath>

#include "analysis/diffraction/field_psf.h"
#include "analysis/diffraction/huygens_psf.h"
#include "analysis/diffraction/matrix_psf.h"
#include "math/constants.h"
#include "paraboloid_bench.h"

namespace lenslab {
namespace {

constexpr double kPsfMirrorFocal = 1000.0, kPsfMirrorDiameter = 100.0;  // F/10

using PsfBench = test::MirrorBench;

PsfBench psf_bench(double field) {
    return test::mirror_bench(kPsfMirrorFocal, kPsfMirrorDiameter, field);
}

TEST(MatrixPsf, EqualsTheFftOnItsGridAndFollowsATilt) {
    const PupilFunction p = make_pupil({32, 2}, 1e-3, 5, [](double x, double y) {
        return 0.2 * (x * x + y * y) * y + 0.1 * x * x;
    });
    const Psf fft = compute_psf(p);
    const Psf matrix = matrix_psf(p, {fft.size, fft.spacing, 0, 0});
    for (size_t k = 0; k < fft.intensity.size(); ++k)
        ASSERT_NEAR(matrix.intensity[k], fft.intensity[k], 1e-9) << k;
    // A tilt of 1.5 waves in x moves a perfect pupil's image to x = 3λN.
    const PupilFunction tilted =
        make_pupil({32, 2}, 1e-3, 5, [](double x, double) { return 1.5 * x; });
    const Psf there = matrix_psf(tilted, {5, 1e-3 * 5 * 0.25, 3 * 1e-3 * 5, 0});
    EXPECT_NEAR(there.at(2, 2), 1.0, 1e-9);
    EXPECT_LT(there.at(2, 3), 1.0);
    EXPECT_NEAR(there.at(2, 1), there.at(2, 3), 1e-9);
}

TEST(FieldPsf, APerfectMirrorHasStrehlOneAndTheAiryEncircledEnergy) {
    const PsfBench b = psf_bench(0);
    FieldPsfOptions o;
    o.image_z = -kPsfMirrorFocal;
    o.wavelengths = {486.1327, 656.2725};
    o.weights = {1, 2};
    const std::vector<FieldPsf> psfs = field_psfs(b.system, b.first, o);
    ASSERT_EQ(psfs.size(), 1u);
    const FieldPsf& f = psfs[0];
    ASSERT_TRUE(f.error.empty()) << f.error;
    EXPECT_TRUE(f.warning.empty()) << f.warning;
    EXPECT_NEAR(f.psf.strehl, 1.0, 2e-3);
    EXPECT_NEAR(f.strehl_per_wavelength[0], 1.0, 2e-3);
    EXPECT_NEAR(f.centroid_x, 0, 1e-9);
    EXPECT_NEAR(f.centroid_y, 0, 1e-9);
    // One wavelength alone for the closed form.
    o.wavelengths = {kLineD};
    o.weights = {};
    const FieldPsf mono = field_psfs(b.system, b.first, o)[0];
    const double lambda_n = kLineD * 1e-6 * 10;
    ASSERT_EQ(mono.radii.size(), 8u);
    for (size_t k = 0; k < mono.radii.size(); ++k) {
        const double v = kPi * mono.radii[k] / lambda_n;
        const double j0 = std::cyl_bessel_j(0.0, v), j1 = std::cyl_bessel_j(1.0, v);
        EXPECT_NEAR(mono.encircled[k], 1 - j0 * j0 - j1 * j1, 0.005) << mono.radii[k];
        EXPECT_GE(mono.ensquared[k], mono.encircled[k] - 1e-12);
    }
}

TEST(FieldPsf, OffTheAxisItIsTheHuygensStrehlAndTheCentroidMoves) {
    const double field = 0.5;
    const PsfBench b = psf_bench(field);
    FieldPsfOptions o;
    o.fields = {0, field, 89};
    o.image_z = -kPsfMirrorFocal - 0.15 * kLineD * 1e-6 * 8 * 100;
    const std::vector<FieldPsf> psfs = field_psfs(b.system, b.first, o);
    ASSERT_EQ(psfs.size(), 3u);
    FieldWavefrontOptions w;
    w.field = field;
    w.wavelength_nm = kLineD;
    w.image_z = o.image_z;
    const FieldWavefront wavefront = field_wavefront(b.system, b.first, w);
    const Psf huygens = huygens_psf(wavefront, {64, 0});
    EXPECT_NEAR(psfs[1].psf.strehl, huygens.strehl, 0.01 * huygens.strehl);
    EXPECT_LT(psfs[1].psf.strehl, psfs[0].psf.strehl);
    // The centroid is not the chief ray's point: coma's flare pulls it along y.
    EXPECT_GT(std::abs(psfs[1].centroid_y - psfs[1].centre_y), 1e-4);
    EXPECT_NEAR(psfs[1].centroid_x, psfs[1].centre_x, 1e-9);
    EXPECT_FALSE(psfs[2].error.empty());
    EXPECT_TRUE(psfs[2].psf.intensity.empty());
}

TEST(FieldPsf, HuygensWaveletsGiveTheTransformsPsf) {
    const double field = 0.5;
    const PsfBench b = psf_bench(field);
    FieldPsfOptions o;
    o.fields = {field};
    o.samples = 32;
    o.wavelengths = {486.1327, 587.5618};
    o.image_z = -kPsfMirrorFocal - 0.15 * kLineD * 1e-6 * 8 * 100;
    const FieldPsf transform = field_psfs(b.system, b.first, o)[0];
    o.method = PsfMethod::Huygens;
    const FieldPsf huygens = field_psfs(b.system, b.first, o)[0];
    ASSERT_EQ(huygens.psf.size, transform.psf.size);
    EXPECT_NEAR(huygens.psf.strehl, transform.psf.strehl, 0.01 * transform.psf.strehl);
    double largest = 0;
    for (size_t k = 0; k < huygens.psf.intensity.size(); ++k)
        largest =
            std::max(largest, std::abs(huygens.psf.intensity[k] - transform.psf.intensity[k]));
    EXPECT_LT(largest, 0.01 * transform.psf.strehl);
}

}  // namespace
}  // namespace lenslab
