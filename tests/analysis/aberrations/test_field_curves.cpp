// Field curves and the chromatic focal shift (field_curves.h, focal_shift.h):
// - at a small aperture and field the Sasian triplet's real tangential and sagittal foci
//   are the third-order ones: a ray through stop point py lands σ py h² from the chief ray
//   (σ = (3 S_III + S_IV) / (2 n'u') tangentially, (S_III + S_IV) / (2 n'u') sagittally,
//   Welford, Aberrations of Optical Systems, 1986, section 8.3) and leaves with the slope
//   u' py relative to it, so the neighbouring rays cross it -σ h² / u' from the paraxial image
//   plane (h: the field as a fraction of the Seidel sums' field); on the axis both are equal;
// - its real chief ray lies σ_V h³ from the paraxial one (σ_V = S_V / (2 n'u'));
// - the focal shift of a plano-convex N-BK7 lens (curved side first) at infinity is
//   BFL(λ) - BFL(λ0), BFL = R / (n - 1) - t / n (Hecht, Optics, eq. 6.3 with R2 -> infinity),
//   n from SCHOTT's published Sellmeier coefficients for N-BK7.

#include <gtest/gtest.h>

#include <cmath>

#include "../lens_scene_builder.h"
#include "../sasian_triplet.h"
#include "analysis/aberrations/field_curves.h"
#include "analysis/aberrations/focal_shift.h"

namespace lenslab {
namespace {

TEST(FieldCurves, SmallFieldFociAndDistortionAreThirdOrder) {
    const OpticalSystem system = test::sasian_triplet();
    const test::SasianThirdOrder third = test::sasian_third_order(system);
    const FirstOrder& f = third.first_order;
    const SeidelTransverse& t = third.transverse;
    FieldCurveOptions o;
    o.max_field = test::kSasianSmallField;
    o.points = 3;  // 0, 0.5, 1 degree
    const FieldCurves curves = field_curves(system, f, o);
    ASSERT_EQ(curves.curves.size(), 1u);
    const std::vector<FieldCurvePoint>& p = curves.curves[0].points;
    ASSERT_EQ(p.size(), 3u);
    const double u = f.marginal.last().u_after;
    EXPECT_NEAR(p[0].tangential, p[0].sagittal, 1e-9);
    EXPECT_TRUE(std::isnan(p[0].distortion));
    for (size_t i : {1u, 2u}) {
        const double h = std::tan(p[i].field * M_PI / 180) / std::tan(f.field * M_PI / 180);
        SCOPED_TRACE(::testing::Message() << "field " << p[i].field);
        const double tangential = p[0].tangential - t.tangential_field * h * h / u;
        const double sagittal = p[0].sagittal - t.sagittal_field * h * h / u;
        EXPECT_NEAR(p[i].tangential, tangential, 0.02 * std::abs(tangential - p[0].tangential));
        EXPECT_NEAR(p[i].sagittal, sagittal, 0.02 * std::abs(sagittal - p[0].sagittal));
        const double shift = t.distortion * h * h * h;
        EXPECT_NEAR(p[i].chief_height - p[i].paraxial_height, shift, 0.02 * std::abs(shift));
    }
    EXPECT_NEAR(p[2].paraxial_height, f.image_height, 1e-12);
}

TEST(FieldCurves, OnTheAxisAloneOneField) {
    const OpticalSystem system = test::sasian_triplet();
    const FirstOrder f = test::sasian_third_order(system).first_order;
    const FieldCurves curves = field_curves(system, f, {});  // max_field 0
    ASSERT_EQ(curves.curves[0].points.size(), 1u);
    EXPECT_EQ(curves.curves[0].points[0].field, 0.0);
}

double schott_n_bk7(double nm) {
    // SCHOTT optical glass data sheet, N-BK7: B1..B3, C1..C3 (µm²).
    const double l2 = std::pow(nm * 1e-3, 2);
    return std::sqrt(1 + 1.03961212 * l2 / (l2 - 0.00600069867) +
                     0.231792344 * l2 / (l2 - 0.0200179144) + 1.01046945 * l2 / (l2 - 103.560653));
}

TEST(FocalShift, PlanoConvexSingletAgainstTheLensFormula) {
    const double r = 51.5, t = 3.6;
    const OpticalSystem system = build_optical_system(test::lens_scene(
        {{"pcx", 0.0, t, 25.4, test::sphere(r), test::sphere(0), test::glass("N-BK7")}}));
    FirstOrderOptions o;
    o.epd = 10;
    const FocalShift s = chromatic_focal_shift(system, o, 450.0, 750.0, 7);
    ASSERT_EQ(s.wavelengths.size(), 7u);
    EXPECT_EQ(s.wavelengths.front(), 450.0);
    EXPECT_EQ(s.wavelengths.back(), 750.0);
    const auto bfl = [&](double nm) {
        const double n = schott_n_bk7(nm);
        return r / (n - 1) - t / n;
    };
    for (size_t i = 0; i < s.wavelengths.size(); ++i) {
        EXPECT_NEAR(s.shift[i], bfl(s.wavelengths[i]) - bfl(kLineD), 1e-6);
    }
    // Blue focuses shorter.
    EXPECT_LT(s.shift.front(), 0);
    EXPECT_GT(s.shift.back(), 0);
}

}  // namespace
}  // namespace lenslab
