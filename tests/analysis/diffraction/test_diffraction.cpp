// Diffraction of sampled pupils (analysis/diffraction/diffraction.h) against closed forms:
// - a perfect F/5 pupil at 550 nm: its MTF against 2/π (φ - cos φ sin φ), φ = arccos(ν/ν_c),
//   with cutoff ν_c = 1/(λN) = 363.6 cycles/mm (Goodman, Introduction to Fourier Optics,
//   3rd ed., section 6.3.3); the first zero of the Airy pattern at 1.22 λN = 3.355 µm and the
//   Airy profile [2 J1(v)/v]², v = π r/(λN) (Born & Wolf, Principles of Optics, 7th ed.,
//   section 8.5.2); Rayleigh's encircled energy 1 - J0²(v) - J1²(v), 0.838 at the first dark
//   ring and 0.910 at the second (Born & Wolf, section 8.5.2);
// - energy: Parseval makes Σ PSF·ΔA = (λN)² D²/(transmitted area), the equivalent area of the
//   Airy disc, 4 (λN)²/π for a full circle (Born & Wolf, section 8.5.2, I0 = P A/(λ² R²));
// - 0.05 λ RMS of defocus (Zernike Z4 = √3 (2ρ² - 1)): Strehl within 0.01 of the Maréchal
//   approximation exp(-(2πσ)²) (Mahajan, Optical Imaging and Aberrations, Part II) and equal
//   to the exact on-axis intensity of a defocused pupil, [sin(πW20)/(πW20)]² with W20 = 2√3 σ
//   the defocus in waves (Born & Wolf, section 8.8.1: [sin(u/4)/(u/4)]², u/4 = π W20);
// - a wavefront tilt moves the PSF by 2 t λN, to the side whose rays travel farther.

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <thread>

#include "analysis/diffraction/diffraction.h"
#include "math/constants.h"

namespace lenslab {
namespace {

constexpr double kDiffractionLambdaMm = 550e-6;  // 550 nm in millimetres
constexpr double kDiffractionFNumber = 5.0;
constexpr double kLambdaN = kDiffractionLambdaMm * kDiffractionFNumber;

PupilFunction perfect_pupil(int samples = 256, int padding = 2) {
    return make_pupil({samples, padding}, kDiffractionLambdaMm, kDiffractionFNumber,
                      [](double, double) { return 0.0; });
}

// Airy radial profile [2 J1(v)/v]², v = π r/(λN).
double airy_intensity(double r) {
    const double v = kPi * r / kLambdaN;
    if (v == 0) return 1;
    const double a = 2 * std::cyl_bessel_j(1.0, v) / v;
    return a * a;
}

TEST(Diffraction, PerfectPupilMtfIsTheDiffractionLimit) {
    const OpticalTransfer otf = compute_otf(compute_psf(perfect_pupil()));
    EXPECT_NEAR(otf.cutoff, 363.636, 0.001);  // cycles/mm
    const std::vector<double> frequencies{20, 80, 160, 250, 330};
    const MtfCurves mtf = mtf_curves(otf, frequencies);
    for (size_t k = 0; k < frequencies.size(); ++k) {
        const double phi = std::acos(frequencies[k] / otf.cutoff);
        const double expected = 2 / kPi * (phi - std::cos(phi) * std::sin(phi));
        EXPECT_NEAR(mtf.diffraction_limit[k], expected, 1e-12);
        EXPECT_NEAR(mtf.tangential[k], expected, 0.005) << frequencies[k];
        EXPECT_NEAR(mtf.sagittal[k], expected, 0.005) << frequencies[k];
    }
    // Nothing passes beyond the cutoff; the zero frequency is 1 by definition.
    EXPECT_LT(otf.modulation(0, 1.01 * otf.cutoff), 1e-9);
    EXPECT_LT(otf.modulation(0.75 * otf.cutoff, 0.75 * otf.cutoff), 1e-9);
    EXPECT_DOUBLE_EQ(otf.modulation(0, 0), 1.0);
    EXPECT_EQ(diffraction_limited_mtf(otf.cutoff, otf.cutoff), 0.0);
    EXPECT_EQ(diffraction_limited_mtf(2 * otf.cutoff, otf.cutoff), 0.0);
}

TEST(Diffraction, DiffractionLimitAtHalfTheCutoff) {
    // φ = π/3: 2/π (π/3 - √3/4) = 0.3910.
    EXPECT_NEAR(diffraction_limited_mtf(0.5, 1.0), 0.3910, 5e-5);
    EXPECT_DOUBLE_EQ(diffraction_limited_mtf(0, 1.0), 1.0);
}

TEST(Diffraction, AiryPatternAndItsFirstZero) {
    const Psf psf = compute_psf(perfect_pupil());
    EXPECT_NEAR(psf.spacing, kLambdaN / 2, 1e-15);
    EXPECT_NEAR(psf.strehl, 1.0, 1e-12);
    const int c = psf.size / 2;
    EXPECT_NEAR(psf.at(c, c), 1.0, 1e-12);
    // The profile along x against the Airy function.
    for (int k = 1; k < 12; ++k)
        EXPECT_NEAR(psf.at(c, c + k), airy_intensity(psf.coordinate(c + k)), 2e-3) << k;
    // The first zero, on the radial profile interpolated from the OTF: bracketed by a scan,
    // then narrowed by golden section (128 samples across the pupil keep the sums short).
    const OpticalTransfer otf = compute_otf(compute_psf(perfect_pupil(128)));
    const auto profile_at = [&](double r) { return radial_profile(otf, {r})[0]; };
    double lo = 1.0 * kLambdaN, hi = 1.5 * kLambdaN;
    const double golden = 0.5 * (std::sqrt(5.0) - 1);
    for (int k = 0; k < 40; ++k) {
        const double a = hi - golden * (hi - lo), b = lo + golden * (hi - lo);
        if (profile_at(a) < profile_at(b))
            hi = b;
        else
            lo = a;
    }
    const double zero = 0.5 * (lo + hi);
    EXPECT_NEAR(1.21967 * kLambdaN, 3.355e-3, 1e-6);
    EXPECT_NEAR(zero, 1.21967 * kLambdaN, psf.spacing);
    EXPECT_NEAR(zero, 1.21967 * kLambdaN, 0.01 * kLambdaN);  // in fact much closer
    EXPECT_LT(profile_at(zero), 1e-4);
    // The profile is the Airy pattern between the samples too.
    for (double v : {0.5, 1.7, 2.9, 5.1})
        EXPECT_NEAR(profile_at(v * kLambdaN / kPi), airy_intensity(v * kLambdaN / kPi), 2e-3) << v;
    // With finer sampling (padding 8) the darkest sample near the ring is the one nearest it.
    const Psf fine = compute_psf(perfect_pupil(128, 8));
    const int cf = fine.size / 2;
    int darkest = cf + 1;
    for (int j = cf + 1; fine.coordinate(j) < 1.5 * kLambdaN; ++j)
        if (fine.coordinate(j) > kLambdaN && fine.at(cf, j) < fine.at(cf, darkest)) darkest = j;
    EXPECT_NEAR(fine.coordinate(darkest), 1.21967 * kLambdaN, 0.5 * fine.spacing);
}

TEST(Diffraction, EncircledEnergyIsRayleighs) {
    const OpticalTransfer otf = compute_otf(compute_psf(perfect_pupil()));
    // Dark rings at v = 3.8317 and 7.0156, and two radii between.
    const std::vector<double> v{1.0, 3.8317, 5.0, 7.0156};
    std::vector<double> radii;
    for (double x : v) radii.push_back(x * kLambdaN / kPi);
    const std::vector<double> energy = encircled_energy(otf, radii);
    for (size_t k = 0; k < v.size(); ++k) {
        const double j0 = std::cyl_bessel_j(0.0, v[k]), j1 = std::cyl_bessel_j(1.0, v[k]);
        EXPECT_NEAR(energy[k], 1 - j0 * j0 - j1 * j1, 0.002) << v[k];
    }
    EXPECT_NEAR(energy[1], 0.838, 0.002);
    EXPECT_NEAR(energy[3], 0.910, 0.002);
    EXPECT_NEAR(encircled_energy(otf, {0.0})[0], 0.0, 1e-15);
}

TEST(Diffraction, PsfEnergyIsThePupilsPower) {
    const PupilFunction pupil = perfect_pupil();
    const Psf psf = compute_psf(pupil);
    double sum = 0;
    for (double v : psf.intensity) sum += v;
    double transmitted = 0;  // Σ A², the samples inside the circle
    for (double a : pupil.amplitude) transmitted += a * a;
    const double diameter = kLambdaN * pupil.samples;  // grid extent λN × samples / padding
    const double area = psf.spacing * psf.spacing;
    // Parseval, exact up to rounding; then the closed form for a full circle.
    EXPECT_NEAR(sum * area, diameter * diameter / transmitted, 1e-9 * sum * area);
    EXPECT_NEAR(sum * area, 4 * kLambdaN * kLambdaN / kPi, 2e-3 * sum * area);
}

TEST(Diffraction, DefocusStrehlMatchesMarechalAndTheExactForm) {
    const double sigma = 0.05;
    const PupilFunction pupil = make_pupil(
        {256, 2}, kDiffractionLambdaMm, kDiffractionFNumber,
        [&](double x, double y) { return sigma * std::sqrt(3.0) * (2 * (x * x + y * y) - 1); });
    EXPECT_NEAR(wavefront_rms(pupil), sigma, 2e-4);
    const Psf psf = compute_psf(pupil);
    const double marechal = std::exp(-std::pow(2 * kPi * sigma, 2));  // 0.9060
    EXPECT_NEAR(psf.strehl, marechal, 0.01);
    const double w20 = 2 * std::sqrt(3.0) * sigma;
    const double sinc = std::sin(kPi * w20) / (kPi * w20);
    EXPECT_NEAR(psf.strehl, sinc * sinc, 1e-3);  // 0.9052
    // Defocus keeps the peak at the reference point.
    EXPECT_NEAR(strehl_at_reference(pupil), psf.strehl, 1e-12);
    // And lowers the MTF below the diffraction limit at mid frequencies.
    const MtfCurves mtf = mtf_curves(compute_otf(psf), {150});
    EXPECT_LT(mtf.tangential[0], mtf.diffraction_limit[0] - 0.01);
}

TEST(Diffraction, TiltMovesThePsfTowardTheLongerPaths) {
    const double t = 1.5;  // waves of tilt at the rim
    const PupilFunction pupil = make_pupil({128, 2}, kDiffractionLambdaMm, kDiffractionFNumber,
                                           [&](double x, double y) { return t * x - 0.5 * t * y; });
    const Psf psf = compute_psf(pupil);
    size_t peak = 0;
    for (size_t k = 0; k < psf.intensity.size(); ++k)
        if (psf.intensity[k] > psf.intensity[peak]) peak = k;
    const int row = static_cast<int>(peak) / psf.size, column = static_cast<int>(peak) % psf.size;
    EXPECT_NEAR(psf.coordinate(column), 2 * t * kLambdaN, 1e-12);
    EXPECT_NEAR(psf.coordinate(row), -t * kLambdaN, 1e-12);
    // A shifted Airy pattern: the Strehl is still 1, but not at the reference point.
    EXPECT_NEAR(psf.strehl, 1.0, 1e-9);
    EXPECT_LT(strehl_at_reference(pupil), 0.1);
    // The MTF ignores where the image is.
    const MtfCurves mtf = mtf_curves(compute_otf(psf), {100, 200});
    for (size_t k = 0; k < 2; ++k) {
        EXPECT_NEAR(mtf.tangential[k], mtf.diffraction_limit[k], 0.005);
        EXPECT_NEAR(mtf.sagittal[k], mtf.diffraction_limit[k], 0.005);
    }
}

TEST(Diffraction, ApodisedPupilIsNormalisedToItsOwnPerfectPeak) {
    const PupilFunction pupil = make_pupil(
        {128, 2}, kDiffractionLambdaMm, kDiffractionFNumber, [](double, double) { return 0.0; },
        1.0);
    const Psf psf = compute_psf(pupil);
    EXPECT_NEAR(psf.strehl, 1.0, 1e-12);
    // A Gaussian taper widens the core: more light at the first Airy zero than the uniform
    // pupil's near-nothing.
    const Psf uniform = compute_psf(perfect_pupil(128, 2));
    const int c = psf.size / 2;
    EXPECT_GT(psf.at(c, c + 2), 2 * uniform.at(c, c + 2));
}

TEST(Diffraction, PupilSamplingIsChecked) {
    const auto flat = [](double, double) { return 0.0; };
    EXPECT_THROW(make_pupil({127, 2}, 1e-3, 5, flat), std::invalid_argument);
    EXPECT_THROW(make_pupil({128, 1}, 1e-3, 5, flat), std::invalid_argument);
    EXPECT_THROW(make_pupil({128, 2}, 0, 5, flat), std::invalid_argument);
    EXPECT_THROW(make_pupil({128, 2}, 1e-3, -1, flat), std::invalid_argument);
    PupilFunction dark = make_pupil({16, 2}, 1e-3, 5, flat);
    std::fill(dark.amplitude.begin(), dark.amplitude.end(), 0.0);
    EXPECT_THROW(compute_psf(dark), std::invalid_argument);
}

TEST(Diffraction, ConcurrentTransformsAgreeWithSerialOnes) {
    // FFTW plans are made under a lock and shared: threads planning and running transforms
    // of several sizes at once get the serial results.
    const std::vector<int> sizes{32, 64, 48, 32, 64, 48};
    std::vector<Psf> serial, parallel(sizes.size());
    const auto pupil_of = [](int samples) {
        return make_pupil({samples, 2}, kDiffractionLambdaMm, kDiffractionFNumber,
                          [](double x, double y) { return 0.3 * x * y + 0.2 * x * x; });
    };
    for (int s : sizes) serial.push_back(compute_psf(pupil_of(s)));
    std::vector<std::thread> threads;
    for (size_t k = 0; k < sizes.size(); ++k)
        threads.emplace_back([&, k] { parallel[k] = compute_psf(pupil_of(sizes[k])); });
    for (std::thread& t : threads) t.join();
    for (size_t k = 0; k < sizes.size(); ++k) EXPECT_EQ(parallel[k].intensity, serial[k].intensity);
}

}  // namespace
}  // namespace lenslab
