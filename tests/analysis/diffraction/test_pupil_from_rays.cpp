// The wavefront of real lenses from exact rays (analysis/diffraction/pupil_from_rays.h):
// - a plano-convex lens (flat side to a collimated beam, n = 1.5, R = -50 mm, f = 100 mm): the
//   ρ⁴ term of its wavefront at the paraxial focus is the Seidel primary spherical aberration
//   W040 = SI/8 with SI = -Σ A² h Δ(u/n) (Welford, Aberrations of Optical Systems, sections 7.3
//   and 8.2), here only the curved surface's -n²(n-1) c³ h⁴; the sign is the opposite of
//   Welford's W (see the header);
// - its least-RMS focus lies midway between the paraxial and the marginal focus, where the
//   defocus balances the primary spherical aberration (W20 = -W40; Mahajan, Optical Imaging
//   and Aberrations, Part I, section 8.3 on balanced aberrations);
// - there its Strehl ratio from the FFT agrees with the Maréchal approximation
//   exp(-(2πσ)²) of the same wavefront's RMS σ (< 0.07 λ);
// - the hyperboloid of conic constant -n² focuses a collimated beam to a point (Hecht,
//   Optics, 5th ed., section 5.2.1): its wavefront is flat to a small fraction of a wave and
//   its MTF at F/5 is the diffraction limit;
// - rays outside the lens are vignetted: zero amplitude;
// - diffraction_figures, the command line's one call, reports those same numbers.

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "../lens_scene_builder.h"
#include "analysis/aberrations/aberrations.h"
#include "analysis/diffraction/diffraction.h"
#include "analysis/diffraction/diffraction_figures.h"
#include "analysis/diffraction/pupil_from_rays.h"
#include "analysis/system/paraxial.h"
#include "math/constants.h"

namespace lenslab {
namespace {

constexpr double kRayPupilIndex = 1.5, kRayPupilRadius = -50.0;
constexpr double kRayPupilNm = 550.0;

OpticalSystem flat_front_lens(const std::string& back) {
    const test::LensSpec l{
        "lens", 0, 5.0, 25.0, test::sphere(0), back, R"({"transparency": 1, "ior": 1.5})"};
    return build_optical_system(test::lens_scene({l}));
}

RayPupilOptions ray_pupil_options(double aperture, int samples = 128) {
    RayPupilOptions o;
    o.wavelength_nm = kRayPupilNm;
    o.aperture_radius = aperture;
    o.sampling = {samples, 2};
    return o;
}

// Least-squares coefficients (a4, a6, a8) of W = a4 ρ⁴ + a6 ρ⁶ + a8 ρ⁸ over the pupil.
std::array<double, 3> even_fit(const PupilFunction& p) {
    double m[3][3] = {}, v[3] = {};
    for (int i = 0; i < p.size; ++i)
        for (int j = 0; j < p.size; ++j) {
            if (p.amplitude[p.index(i, j)] == 0) continue;
            const double r2 = p.coordinate(i) * p.coordinate(i) + p.coordinate(j) * p.coordinate(j);
            const double basis[3] = {r2 * r2, r2 * r2 * r2, r2 * r2 * r2 * r2};
            for (int a = 0; a < 3; ++a) {
                v[a] += basis[a] * p.opd_waves[p.index(i, j)];
                for (int b = 0; b < 3; ++b) m[a][b] += basis[a] * basis[b];
            }
        }
    // Cramer's rule on the 3 × 3 normal equations.
    const auto det = [](const double x[3][3]) {
        return x[0][0] * (x[1][1] * x[2][2] - x[1][2] * x[2][1]) -
               x[0][1] * (x[1][0] * x[2][2] - x[1][2] * x[2][0]) +
               x[0][2] * (x[1][0] * x[2][1] - x[1][1] * x[2][0]);
    };
    std::array<double, 3> out{};
    for (int c = 0; c < 3; ++c) {
        double mc[3][3];
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) mc[a][b] = b == c ? v[a] : m[a][b];
        out[c] = det(mc) / det(m);
    }
    return out;
}

TEST(PupilFromRays, PlanoConvexSphericalAberrationIsSeidels) {
    const OpticalSystem lens = flat_front_lens(test::sphere(kRayPupilRadius));
    const double n = kRayPupilIndex, c = 1 / kRayPupilRadius;
    for (double aperture : {4.0, 8.0}) {
        const RayWavefront wavefront(lens, ray_pupil_options(aperture));
        EXPECT_NEAR(wavefront.f_number(), 100.0 / (2 * aperture), 1e-9);
        const PupilFunction pupil = wavefront.pupil(wavefront.paraxial_focus_z());
        const double si = -n * n * (n - 1) * c * c * c * std::pow(aperture, 4);
        const double w040_waves = si / 8 / wavefront.wavelength();
        const std::array<double, 3> fit = even_fit(pupil);
        EXPECT_NEAR(fit[0], -w040_waves, 0.005 * w040_waves) << aperture;
        // Higher orders stay small against the primary term.
        EXPECT_LT(std::abs(fit[1]), 0.05 * w040_waves) << aperture;
    }
}

TEST(PupilFromRays, BestFocusBalancesSphericalAberrationAndMeetsMarechal) {
    const OpticalSystem lens = flat_front_lens(test::sphere(kRayPupilRadius));
    const double aperture = 4.0;  // F/12.5: W040 ≈ 0.51 λ
    const RayWavefront wavefront(lens, ray_pupil_options(aperture));
    const double z_best = wavefront.best_focus_z();
    // Midway between the paraxial focus and where the marginal ray crosses the axis.
    const ParaxialResult paraxial = paraxial_trace(lens, kRayPupilNm);
    const std::vector<LsaPoint> lsa =
        longitudinal_spherical_aberration(lens, paraxial, aperture, 1);
    ASSERT_EQ(lsa.size(), 1u);
    EXPECT_NEAR(z_best - paraxial.z_rear_focus, 0.5 * lsa[0].lsa, 0.03 * std::abs(lsa[0].lsa));
    // Least RMS there: nearby spheres do worse.
    const double rms_best = wavefront.rms_waves(z_best);
    for (double dz : {-0.05, 0.05}) EXPECT_GT(wavefront.rms_waves(z_best + dz), rms_best);
    // Balanced: the RMS falls from W040·√(4/45) at the paraxial focus to W040/(6√5).
    EXPECT_NEAR(wavefront.rms_waves(paraxial.z_rear_focus) / rms_best, 4.0, 0.1);

    const PupilFunction pupil = wavefront.pupil(z_best);
    const double sigma = wavefront_rms(pupil);
    EXPECT_NEAR(sigma, rms_best, 1e-9);
    ASSERT_LT(sigma, 0.07);
    const Psf psf = compute_psf(pupil);
    EXPECT_NEAR(psf.strehl, std::exp(-std::pow(2 * kPi * sigma, 2)), 0.01);
    EXPECT_LT(psf.strehl, 0.99);
    // The paraxial focus is much worse than the best one.
    EXPECT_LT(compute_psf(wavefront.pupil(paraxial.z_rear_focus)).strehl, psf.strehl - 0.2);
}

TEST(PupilFromRays, HyperboloidIsDiffractionLimitedAtF5) {
    const std::string k = std::to_string(-kRayPupilIndex * kRayPupilIndex);
    const OpticalSystem lens =
        flat_front_lens(R"({"shape": "conic", "radius": -50, "k": )" + k + "}");
    const RayWavefront wavefront(lens, ray_pupil_options(10.0));
    EXPECT_NEAR(wavefront.f_number(), 5.0, 1e-9);
    const PupilFunction pupil = wavefront.pupil(wavefront.paraxial_focus_z());
    EXPECT_LT(wavefront_rms(pupil), 1e-3);
    const Psf psf = compute_psf(pupil);
    EXPECT_GT(psf.strehl, 0.999);
    const OpticalTransfer otf = compute_otf(psf);
    EXPECT_NEAR(otf.cutoff, 363.636, 0.001);
    const MtfCurves mtf = mtf_curves(otf, {20, 80, 160, 250, 330});
    for (size_t i = 0; i < mtf.frequencies.size(); ++i) {
        EXPECT_NEAR(mtf.tangential[i], mtf.diffraction_limit[i], 0.005) << mtf.frequencies[i];
        EXPECT_NEAR(mtf.sagittal[i], mtf.diffraction_limit[i], 0.005) << mtf.frequencies[i];
    }
}

TEST(PupilFromRays, RaysOutsideTheLensAreVignetted) {
    const OpticalSystem lens = flat_front_lens(test::sphere(kRayPupilRadius));
    const double aperture = 14.0;  // the lens is 25 mm across
    const RayWavefront wavefront(lens, ray_pupil_options(aperture, 64));
    const PupilFunction pupil = wavefront.pupil(wavefront.paraxial_focus_z());
    int inside = 0, passed = 0;
    for (int i = 0; i < pupil.size; ++i)
        for (int j = 0; j < pupil.size; ++j) {
            const double rho = std::hypot(pupil.coordinate(i), pupil.coordinate(j));
            const bool lit = pupil.amplitude[pupil.index(i, j)] > 0;
            if (rho <= 1) ++inside;
            passed += lit;
            if (lit) {
                EXPECT_LE(rho * aperture, 12.5);
            }
            if (rho * aperture < 12.3) {
                EXPECT_TRUE(lit) << i << " " << j;
            }
        }
    EXPECT_NEAR(static_cast<double>(passed) / inside, std::pow(12.5 / aperture, 2), 0.02);
    // The default aperture is the usable one: the whole lens.
    RayPupilOptions whole = ray_pupil_options(0, 32);
    EXPECT_DOUBLE_EQ(RayWavefront(lens, whole).aperture_radius(), 12.5);
}

TEST(PupilFromRays, FiguresForTheCommandLineAreTheSameNumbers) {
    const OpticalSystem lens = flat_front_lens(test::sphere(kRayPupilRadius));
    const RayPupilOptions options = ray_pupil_options(4.0);
    const RayWavefront wavefront(lens, options);
    const std::vector<double> frequencies = default_mtf_frequencies(1 / (550e-6 * 12.5), 5);
    ASSERT_EQ(frequencies.size(), 5u);
    EXPECT_NEAR(frequencies.back(), 145.4545, 1e-4);  // the cutoff at F/12.5

    const DiffractionFigures best = diffraction_figures(lens, options, frequencies);
    EXPECT_DOUBLE_EQ(best.image_z, wavefront.best_focus_z());
    const PupilFunction pupil = wavefront.pupil(best.image_z);
    EXPECT_DOUBLE_EQ(best.wavefront_rms, wavefront_rms(pupil));
    EXPECT_DOUBLE_EQ(best.strehl, compute_psf(pupil).strehl);
    EXPECT_DOUBLE_EQ(best.f_number, 12.5);
    EXPECT_DOUBLE_EQ(best.aperture_radius, 4.0);
    EXPECT_NEAR(best.airy_radius, 1.21967 * 550e-6 * 12.5, 2e-9);
    // Aberrations move light out of the Airy disc: less than a perfect lens's 0.838.
    EXPECT_LT(best.encircled_energy_at_airy_radius, 0.83);
    EXPECT_GT(best.encircled_energy_at_airy_radius, 0.7);
    ASSERT_EQ(best.mtf.tangential.size(), 5u);
    for (size_t k = 0; k + 1 < 5; ++k) {
        EXPECT_LE(best.mtf.tangential[k], best.mtf.diffraction_limit[k] + 1e-3);
        EXPECT_NEAR(best.mtf.tangential[k], best.mtf.sagittal[k], 1e-9);  // on the axis
    }
    EXPECT_NEAR(best.mtf.tangential.back(), 0.0, 1e-6);

    const DiffractionFigures paraxial =
        diffraction_figures(lens, options, frequencies, DiffractionFocus::Paraxial);
    EXPECT_DOUBLE_EQ(paraxial.image_z, wavefront.paraxial_focus_z());
    EXPECT_LT(paraxial.strehl, best.strehl - 0.2);

    // No frequencies asked for: ten up to the cutoff.
    const DiffractionFigures defaults = diffraction_figures(lens, options, {});
    ASSERT_EQ(defaults.mtf.frequencies.size(), 10u);
    EXPECT_NEAR(defaults.mtf.frequencies.back(), 145.4545, 1e-4);
    EXPECT_NEAR(defaults.mtf.tangential[3], best.mtf.tangential[1], 1e-12);  // both 0.4 ν_c
}

}  // namespace
}  // namespace lenslab
