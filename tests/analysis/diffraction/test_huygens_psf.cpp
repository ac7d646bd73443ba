// The Huygens PSF (analysis/diffraction/huygens_psf.h) against the FFT PSF (diffraction.h):
// - a perfect F/10 paraboloid on its axis peaks at 1 (the normalisation) and, one Airy radius
//   (1.22 λN) away, is dark: the first zero of the Airy pattern [2 J1(v)/v]²;
// - off the axis (0.5°, coma and astigmatism) and defocused by 0.15 wave
//   more (Strehl 0.71), the two methods' PSFs agree sample by sample within 1% of the peak and
//   their Strehl ratios within 1% (issue 42's test): the Fraunhofer approximation holds at F/10, so
//   any difference would be a sign or scale error in one of them;
// - a grid placed off the reference point finds the comatic PSF where the FFT has it.

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "analysis/diffraction/huygens_psf.h"
#include "paraboloid_bench.h"

namespace lenslab {
namespace {

constexpr double kHuygensFocal = 1000.0, kHuygensDiameter = 100.0;  // F/10

using HuygensBench = test::MirrorBench;

HuygensBench huygens_bench(double field) {
    return test::mirror_bench(kHuygensFocal, kHuygensDiameter, field);
}

FieldWavefront huygens_wavefront(const HuygensBench& b, double field, double defocus_waves) {
    FieldWavefrontOptions o;
    o.field = field;
    o.wavelength_nm = kLineD;
    const double n = kHuygensFocal / kHuygensDiameter;
    o.image_z = -kHuygensFocal - defocus_waves * kLineD * 1e-6 * 8 * n * n;
    return field_wavefront(b.system, b.first, o);
}

TEST(HuygensPsf, APerfectMirrorIsTheAiryPattern) {
    const HuygensBench b = huygens_bench(0);
    const FieldWavefront w = huygens_wavefront(b, 0, 0);
    const double lambda_n = kLineD * 1e-6 * 10;
    // One sample at the centre, its neighbour at the first dark ring.
    const Psf psf = huygens_psf(w, {3, 1.21967 * lambda_n});
    EXPECT_NEAR(psf.at(1, 1), 1.0, 1e-3);
    EXPECT_NEAR(psf.strehl, 1.0, 1e-3);
    EXPECT_LT(psf.at(1, 2), 2e-3);
    EXPECT_LT(psf.at(0, 1), 2e-3);
}

TEST(HuygensPsf, AgreesWithTheFftOffTheAxis) {
    const double field = 0.5;
    const HuygensBench b = huygens_bench(field);
    const FieldWavefront w = huygens_wavefront(b, field, 0.15);
    const Psf fft = compute_psf(w.pupil);  // 128 a side, λN/2 apart
    const Psf huygens = huygens_psf(w, {64, 0});
    ASSERT_DOUBLE_EQ(huygens.spacing, fft.spacing);
    double largest_difference = 0;
    for (int i = 0; i < 64; ++i)
        for (int j = 0; j < 64; ++j)
            largest_difference =
                std::max(largest_difference, std::abs(huygens.at(i, j) - fft.at(i + 32, j + 32)));
    EXPECT_LT(largest_difference, 0.01 * fft.strehl);
    EXPECT_NEAR(huygens.strehl, fft.strehl, 0.01 * fft.strehl);
    EXPECT_LT(fft.strehl, 0.97);  // aberrated, not a perfect pupil's PSF
    EXPECT_GT(fft.strehl, 0.5);
}

TEST(HuygensPsf, RefusesAnEmptyGrid) {
    const HuygensBench b = huygens_bench(0);
    const FieldWavefront w = huygens_wavefront(b, 0, 0);
    EXPECT_THROW(huygens_psf(w, {0, 0}), std::invalid_argument);
    EXPECT_THROW(huygens_psf(w, {8, -1}), std::invalid_argument);
}

}  // namespace
}  // namespace lenslab
