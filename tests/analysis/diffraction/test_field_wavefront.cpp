// The wavefront at any field from real rays (analysis/diffraction/field_wavefront.h):
// - a paraboloid mirror images an axial point perfectly: its OPD on the axis at the paraxial
//   focus is zero to rounding;
// - off the axis, with the stop at the mirror, its coma is the sphere's (the chief ray meets
//   the vertex, where the conic does not matter): W131 = f θ / (32 N³) (Schroeder,
//   Astronomical Optics, 2nd ed., section 6.2: sagittal angular coma θ / (16 N²)), which is the
//   Seidel S_II / 2 of lenslab's seidel.h; in the Noll Zernike fit (zernike.h) it is the Z7
//   coefficient W131 / (3√8);
// - referred to the centroid (refer_to_centroid) the tilt goes, coma stays and the centre
//   moves by 2tλN;
// - on the axis of a plano-convex lens it is the axial wavefront of pupil_from_rays.h;
// - a central hole in the mirror takes its share of the pupil, (30/100)² (an obscured
//   pupil: the chief ray through the hole still sets the reference).

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "../lens_scene_builder.h"
#include "analysis/aberrations/seidel.h"
#include "analysis/diffraction/field_wavefront.h"
#include "analysis/diffraction/pupil_from_rays.h"
#include "analysis/diffraction/zernike.h"
#include "analysis/system/paraxial.h"
#include "math/constants.h"
#include "paraboloid_bench.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

constexpr double kParaboloidFocal = 1000.0, kParaboloidDiameter = 100.0;  // F/10

OpticalSystem paraboloid_mirror_system(double hole = 0) {
    return test::paraboloid_mirror(kParaboloidFocal, kParaboloidDiameter, hole);
}

FirstOrder wavefront_first_order(const OpticalSystem& system, double epd, double field) {
    return test::mirror_first_order(system, epd, field);
}

FieldWavefrontOptions wavefront_options(double field) {
    FieldWavefrontOptions o;
    o.field = field;
    o.wavelength_nm = kLineD;
    return o;
}

TEST(FieldWavefront, AParaboloidIsPerfectOnTheAxis) {
    const OpticalSystem system = paraboloid_mirror_system();
    const FirstOrder f = wavefront_first_order(system, kParaboloidDiameter, 0);
    const FieldWavefront w = field_wavefront(system, f, wavefront_options(0));
    EXPECT_NEAR(w.image_z, -kParaboloidFocal, 1e-9);
    EXPECT_NEAR(w.reference.z, -kParaboloidFocal, 1e-9);
    EXPECT_EQ(w.lost, 0);
    EXPECT_GT(w.passed, 3000);  // 64 samples across: π 32² ≈ 3200 inside the pupil
    EXPECT_LT(w.pv_waves, 1e-6);
    EXPECT_LT(w.rms_waves, 1e-7);
}

TEST(FieldWavefront, AParaboloidsComaOffTheAxisIsTheClosedForm) {
    const OpticalSystem system = paraboloid_mirror_system();
    const double degrees = 0.5, theta = degrees * kPi / 180;
    const FirstOrder f = wavefront_first_order(system, kParaboloidDiameter, degrees);
    const FieldWavefront w = field_wavefront(system, f, wavefront_options(degrees));
    const double n = kParaboloidFocal / kParaboloidDiameter;
    const double w131_waves = kParaboloidFocal * theta / (32 * n * n * n) / (kLineD * 1e-6);
    ASSERT_NEAR(w131_waves, 0.4641, 1e-4);
    const ZernikeFit fit = fit_zernike(w.pupil, ZernikeOrdering::Noll, 37);
    const double z7 = fit.coefficients[6];
    EXPECT_NEAR(std::abs(z7), w131_waves / (3 * std::sqrt(8.0)), 0.01 * w131_waves);
    // The same as the Seidel sum: W131 = S_II / 2 at the edge of the field, in waves.
    const Seidel seidel = seidel_sums(system, f, kLineF, kLineC);
    EXPECT_NEAR(std::abs(z7) * 3 * std::sqrt(8.0),
                std::abs(seidel.total.coma) / 2 / (kLineD * 1e-6), 0.01 * w131_waves);
    // Coma is odd in y and even in x: no x-coma (Z8), and the sagittal terms vanish.
    EXPECT_LT(std::abs(fit.coefficients[7]), 1e-6);
    EXPECT_LT(std::abs(fit.coefficients[1]), 1e-6);
}

TEST(FieldWavefront, ReferredToTheCentroidItLosesItsTiltAndKeepsItsComa) {
    const OpticalSystem system = paraboloid_mirror_system();
    const double degrees = 0.5;
    const FirstOrder f = wavefront_first_order(system, kParaboloidDiameter, degrees);
    const FieldWavefront chief = field_wavefront(system, f, wavefront_options(degrees));
    FieldWavefront centroid = chief;
    refer_to_centroid(centroid);
    const ZernikeFit before = fit_zernike(chief.pupil, ZernikeOrdering::Noll, 11);
    const ZernikeFit after = fit_zernike(centroid.pupil, ZernikeOrdering::Noll, 11);
    // The tilt is the least-squares plane: after it, the plane fit (Noll Z1-Z3) has no tilt.
    const ZernikeFit tilt_before = fit_zernike(chief.pupil, ZernikeOrdering::Noll, 3);
    const ZernikeFit tilt_after = fit_zernike(centroid.pupil, ZernikeOrdering::Noll, 3);
    EXPECT_GT(std::abs(tilt_before.coefficients[2]), 1e-3);  // the chief ray leaves tilt
    EXPECT_NEAR(tilt_after.coefficients[1], 0, 1e-12);
    EXPECT_NEAR(tilt_after.coefficients[2], 0, 1e-12);
    EXPECT_NEAR(after.coefficients[6], before.coefficients[6], 1e-9);  // coma is kept
    EXPECT_LT(centroid.rms_waves, chief.rms_waves);
    // The Noll Z3 = 2ρ sin θ tilt moves the centre by 2 · (2 Z3) λN along y.
    const double lambda_n = kLineD * 1e-6 * f.working_f_number;
    EXPECT_NEAR(centroid.reference.y - chief.reference.y,
                4 * tilt_before.coefficients[2] * lambda_n, 1e-9 * lambda_n);
    EXPECT_NEAR(centroid.reference.x, chief.reference.x, 1e-15);
}

TEST(FieldWavefront, OnTheAxisItIsTheAxialWavefront) {
    const test::LensSpec l{"lens",
                           0,
                           5.0,
                           25.0,
                           test::sphere(0),
                           test::sphere(-50),
                           R"({"transparency": 1, "ior": 1.5})"};
    const OpticalSystem system = build_optical_system(test::lens_scene({l}));
    const double radius = 10;
    FirstOrderOptions o;
    o.wavelength_nm = 550;
    o.stop = 0;
    o.epd = 2 * radius;
    const FirstOrder f = first_order(system, paraxial_trace(system, 550), o);
    FieldWavefrontOptions options = wavefront_options(0);
    options.wavelength_nm = 550;
    const FieldWavefront w = field_wavefront(system, f, options);
    RayPupilOptions axial;
    axial.wavelength_nm = 550;
    axial.aperture_radius = radius;
    axial.sampling = options.sampling;
    axial.pupil_z = system.last_vertex() + f.exit_pupil.position;
    const RayWavefront reference(system, axial);
    EXPECT_GT(w.rms_waves, 0.5);  // a strongly undercorrected singlet at F/5
    EXPECT_NEAR(w.rms_waves, reference.rms_waves(reference.paraxial_focus_z()), 1e-6 * w.rms_waves);
}

TEST(FieldWavefront, ACentralHoleObscuresItsShareOfThePupil) {
    // A hole of 30 in the mirror of 100: (30/100)² of the pupil's area is lost; the chief ray,
    // through the hole, still sets the reference.
    const OpticalSystem system = paraboloid_mirror_system(30);
    const FirstOrder f = wavefront_first_order(system, kParaboloidDiameter, 0);
    const FieldWavefront w = field_wavefront(system, f, wavefront_options(0));
    EXPECT_NEAR(static_cast<double>(w.lost) / (w.lost + w.passed), 0.09, 0.01);
    EXPECT_LT(w.pv_waves, 1e-6);
}

TEST(FieldWavefront, BadSamplingIsRefused) {
    const OpticalSystem system = paraboloid_mirror_system();
    const FirstOrder f = wavefront_first_order(system, kParaboloidDiameter, 0);
    FieldWavefrontOptions options = wavefront_options(0);
    options.sampling.samples = 33;
    EXPECT_THROW(field_wavefront(system, f, options), std::invalid_argument);
}

}  // namespace
}  // namespace lenslab
