// Transverse ray fans (ray_fans.h):
// - at a small aperture and field the Sasian triplet's fans are the Seidel polynomial
//   (Welford, Aberrations of Optical Systems, 1986, section 8.3; σ = S / (2 n'u') at the
//   edge of pupil and field): tangential ε_y = σ_I py³ + 3 σ_II py² + (3 σ_III + σ_IV) py,
//   sagittal ε_x = σ_I px³ + (σ_III + σ_IV) px;
// - on the axis of a singlet, the F line's fan against the d line's chief ray (the axis) in
//   the d line's paraxial image plane is its longitudinal colour seen across: the F ray
//   through stop point py leaves with the paraxial slope -py (D/2) / f_F and crosses the axis
//   at the F focus, so in the d plane it is at -py (D/2) / f_F (BFL_d - BFL_F);
// - off the axis the fans at py = 0 (the chief rays of the other wavelengths) are the lateral
//   colour: ε(F) - ε(C) = C_II / (n'u') at a small field (Welford 8.3), and the primary's
//   is zero by definition.

#include <gtest/gtest.h>

#include <cmath>

#include "../lens_scene_builder.h"
#include "../sasian_triplet.h"
#include "analysis/aberrations/ray_fans.h"
#include "analysis/aberrations/seidel.h"

namespace lenslab {
namespace {

FirstOrder fans_first_order(const OpticalSystem& system, const FirstOrderOptions& o) {
    return first_order(system, paraxial_trace(system, o.wavelength_nm), o);
}

// The triplet's fans at its small field and aperture (sasian_third_order).
RayFans third_order_fans(const OpticalSystem& system, const FirstOrder& f,
                         const std::vector<double>& wavelengths, int points) {
    RayFanOptions o;
    o.fields = {test::kSasianSmallField};
    o.wavelengths = wavelengths;
    o.points = points;
    return ray_fans(system, f, o);
}

TEST(RayFans, SmallApertureFansAreTheSeidelPolynomial) {
    const OpticalSystem system = test::sasian_triplet();
    const test::SasianThirdOrder third = test::sasian_third_order(system);
    const SeidelTransverse& t = third.transverse;
    const RayFans r = third_order_fans(system, third.first_order, {}, 9);
    ASSERT_EQ(r.pupil.size(), 9u);
    EXPECT_EQ(r.pupil.front(), -1.0);
    EXPECT_EQ(r.pupil.back(), 1.0);
    const RayFan& fan = r.fields[0].fans[0];
    for (size_t i = 0; i < r.pupil.size(); ++i) {
        const double p = r.pupil[i];
        SCOPED_TRACE(::testing::Message() << "pupil " << p);
        const double ey =
            t.spherical * p * p * p + t.tangential_coma * p * p + t.tangential_field * p;
        const double ex = t.spherical * p * p * p + t.sagittal_field * p;
        // Near the chief ray the errors vanish; compare against the fan's full size there.
        const double tol_y = 0.02 * std::max(std::abs(ey), 0.2 * std::abs(t.tangential_field));
        const double tol_x = 0.02 * std::max(std::abs(ex), 0.2 * std::abs(t.sagittal_field));
        EXPECT_NEAR(fan.tangential[i], ey, tol_y);
        EXPECT_NEAR(fan.sagittal[i], ex, tol_x);
    }
}

TEST(RayFans, AxialColourOfASinglet) {
    const OpticalSystem system =
        build_optical_system(test::lens_scene({{"biconvex", 0.0, 5.0, 30.0, test::sphere(100.0),
                                                test::sphere(-100.0), test::glass("N-BK7")}}));
    FirstOrderOptions o;
    o.epd = 10.0;
    const FirstOrder f = fans_first_order(system, o);
    RayFanOptions fo;
    fo.wavelengths = {kLineF, kLineD};
    fo.points = 21;  // pupil[11] = 0.1: small enough that spherical aberration is negligible
    const RayFans r = ray_fans(system, f, fo);
    const ParaxialResult blue = paraxial_trace(system, kLineF), d = paraxial_trace(system, kLineD);
    for (size_t i : {9u, 11u}) {
        const double p = r.pupil[i];
        const double expected = -p * 0.5 * o.epd / blue.efl * (d.bfl - blue.bfl);
        // Both fans carry the same spherical aberration; the F line's excess is the colour.
        const double excess = r.fields[0].fans[0].tangential[i] - r.fields[0].fans[1].tangential[i];
        EXPECT_NEAR(excess, expected, 0.01 * std::abs(expected));
        EXPECT_NEAR(r.fields[0].fans[0].sagittal[i], r.fields[0].fans[0].tangential[i], 1e-12);
    }
}

TEST(RayFans, LateralColourAtTheChiefRay) {
    const OpticalSystem system = test::sasian_triplet();
    const test::SasianThirdOrder third = test::sasian_third_order(system);
    // Three points: -1, 0, 1.
    const RayFans r =
        third_order_fans(system, third.first_order, {kLineF, test::kSasianNm, kLineC}, 3);
    const FieldFans& field = r.fields[0];
    EXPECT_EQ(field.fans[1].tangential[1], 0.0);
    const double lateral = field.fans[0].tangential[1] - field.fans[2].tangential[1];
    const double expected = third.transverse.lateral_colour;
    EXPECT_NEAR(lateral, expected, 0.02 * std::abs(expected));
}

}  // namespace
}  // namespace lenslab
