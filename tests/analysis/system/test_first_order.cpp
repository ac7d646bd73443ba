// First-order data of a textbook Cooke triplet against a published paraxial trace: the
// triplet of the rayoptics documentation's "Triplet example" (sasian_triplet.h). The page
// prints the paraxial marginal and chief rays at every surface (`pm.list_model()`: heights
// and reduced slopes n u, six significant figures) and the first-order data
// (`pm.first_order_data()`, four figures: efl 50, bfl 41.24, f/# 4, enp_dist 11.68,
// exp_dist -10.01, exp_radius 6.406, img_ht 18.2, optical invariant 2.275). The figures
// below are the page's: the ray table as printed, and the first-order data to six figures
// from that table (EFL = y1 / -(n'u'), and so on, as noted).

#include <gtest/gtest.h>

#include <cmath>

#include "../lens_scene_builder.h"
#include "../sasian_triplet.h"
#include "analysis/system/first_order.h"
#include "util/scene_error.h"

namespace lenslab {
namespace {

using test::glass;
using test::lens_scene;
using test::LensSpec;
using test::sasian_triplet;
using test::sphere;

FirstOrder sasian_first_order() {
    const OpticalSystem system = sasian_triplet();
    const FirstOrderOptions o = test::sasian_options();
    return first_order(system, paraxial_trace(system, o.wavelength_nm), o);
}

// The page's figures have six significant figures: 1e-5 relative holds them, with a floor
// for the values that print as a few units in the sixth decimal.
void expect_rayoptics_figure(double got, double want, const char* what) {
    EXPECT_NEAR(got, want, std::max(1e-5 * std::abs(want), 2e-6)) << what;
}

TEST(FirstOrderCookeTriplet, RayTableMatchesRayoptics) {
    const FirstOrder f = sasian_first_order();
    // pm.list_model() rows 1-6: ax_ht, ax_slp (n u after the surface), pr_ht, pr_slp.
    const double table[6][4] = {
        {6.25, -0.182126, -4.25088, 0.487842},        {5.72969, -0.181586, -2.85718, 0.487573},
        {4.66559, -0.0532508, 3.53405e-07, 0.487573}, {4.63455, 0.0891357, 0.2842, 0.496304},
        {5.06436, 0.0488, 2.67738, 0.47498},          {5.1546, -0.124998, 3.55571, 0.355092},
    };
    ASSERT_EQ(f.marginal.surfaces.size(), 6u);
    for (int i = 0; i < 6; ++i) {
        SCOPED_TRACE(i + 1);
        const ParaxialRaySurface& m = f.marginal.surfaces[i];
        const ParaxialRaySurface& c = f.chief.surfaces[i];
        expect_rayoptics_figure(m.y, table[i][0], "marginal y");
        expect_rayoptics_figure(m.n_after * m.u_after, table[i][1], "marginal n u");
        expect_rayoptics_figure(c.y, table[i][2], "chief y");
        expect_rayoptics_figure(c.n_after * c.u_after, table[i][3], "chief n u");
    }
}

TEST(FirstOrderCookeTriplet, PupilsFocalLengthAndFNumberMatchRayoptics) {
    const FirstOrder f = sasian_first_order();
    // From the page's last row (y = 5.1546, n'u' = -0.124998; chief 3.55571, 0.355092), its
    // first row (chief height -4.25088 at slope tan 20 deg) and its last air gap 41.2365 plus
    // the residual image height 0.000143648 (row 7):
    const double efl = 6.25 / 0.124998;                          // 50.0008 (efl 50)
    const double bfl = 41.2365 + 0.000143648 / 0.124998;         // 41.2376 (bfl 41.24)
    const double enp = 4.25088 / std::tan(20.0 * M_PI / 180.0);  // 11.6792 (enp_dist 11.68)
    const double exp = -3.55571 / 0.355092;                      // -10.0135 (exp_dist -10.01)
    const double exd = 2.0 * (5.1546 - 0.124998 * exp);          // 12.8126 (exp_radius 6.406)
    const double h = 0.363970 * 6.25;                            // 2.27481 (invariant 2.275)
    EXPECT_NEAR(f.efl, efl, 1e-5 * efl);
    EXPECT_NEAR(f.bfl, bfl, 1e-5 * bfl);
    EXPECT_NEAR(f.entrance_pupil.position, enp, 1e-5 * enp);
    EXPECT_DOUBLE_EQ(f.entrance_pupil.diameter, 12.5);
    EXPECT_NEAR(f.exit_pupil.position, exp, 1e-5 * std::abs(exp));
    EXPECT_NEAR(f.exit_pupil.diameter, exd, 1e-5 * exd);
    EXPECT_NEAR(f.f_number, efl / 12.5, 1e-5 * 4.0);  // f/# 4
    EXPECT_NEAR(f.lagrange_invariant, h, 1e-5 * h);
    // Row 7, the page's image plane (41.2365 behind the last vertex, a hair in front of the
    // paraxial focus): the chief ray's height there.
    const OpticalSystem system = sasian_triplet();
    EXPECT_NEAR(f.chief.height_after(system, system.last_vertex() + 41.2365), 18.1985,
                1e-5 * 18.1985);
    EXPECT_NEAR(f.na, 0.124998, 1e-5);  // na img 0.124 (n' = 1)
    EXPECT_FALSE(f.magnification.has_value());
}

TEST(FirstOrder, StopOnTheFirstSurfaceIsTheEntrancePupil) {
    const OpticalSystem system = sasian_triplet();
    FirstOrderOptions o;
    o.epd = 10.0;
    const FirstOrder f = first_order(system, paraxial_trace(system, kLineD), o);
    EXPECT_DOUBLE_EQ(f.entrance_pupil.position, 0.0);
    EXPECT_DOUBLE_EQ(f.stop_semi_diameter, 5.0);
    EXPECT_NEAR(f.f_number, f.efl / 10.0, 1e-12);
}

TEST(FirstOrder, FNumberSetsTheEntrancePupil) {
    const OpticalSystem system = sasian_triplet();
    FirstOrderOptions o;
    o.stop = 2;
    o.f_number = 5.0;
    const FirstOrder f = first_order(system, paraxial_trace(system, kLineD), o);
    EXPECT_NEAR(f.entrance_pupil.diameter, f.efl / 5.0, 1e-12);
    EXPECT_NEAR(f.f_number, 5.0, 1e-12);
}

// A thin-ish singlet at finite conjugates: the magnification and working F-number against
// the Newtonian relations, m = -f / x (x: object distance from the front focal point) and
// N_w = (1 - m) N for an object in air, stop at the lens.
TEST(FirstOrder, FiniteObjectMagnificationAndWorkingFNumber) {
    const OpticalSystem system = build_optical_system(
        lens_scene({{"lens", 0.0, 3.0, 20.0, sphere(40.0), sphere(-40.0), glass("N-BK7")}}));
    const ParaxialResult p = paraxial_trace(system, kLineD);
    FirstOrderOptions o;
    o.epd = 8.0;
    o.object_distance = 150.0;
    o.fields = {5.0};  // an object height
    const FirstOrder f = first_order(system, p, o);
    const double x = o.object_distance.value() - p.ffl;  // front focal point to the object
    const double m = -p.efl / x;
    ASSERT_TRUE(f.magnification.has_value());
    EXPECT_NEAR(*f.magnification, m, 1e-9 * std::abs(m));
    EXPECT_NEAR(f.image_height, 5.0 * m, 1e-9 * std::abs(5.0 * m));
    // Newton: the image lies f² / x behind the rear focal point.
    EXPECT_NEAR(f.image_position, p.bfl + p.efl * p.efl / x, 1e-9 * p.bfl);
    // With the stop on the first surface the entrance pupil is there, so the working
    // F-number follows from the cone the image receives: the marginal ray reaches the image
    // from the exit pupil.
    const double xp_to_image = f.image_position - f.exit_pupil.position;
    EXPECT_NEAR(f.working_f_number, xp_to_image / f.exit_pupil.diameter, 1e-9 * f.working_f_number);
}

TEST(FirstOrder, RefusesAStopOutsideTheSystem) {
    const OpticalSystem system = sasian_triplet();
    FirstOrderOptions o;
    o.stop = 6;
    EXPECT_THROW(first_order(system, paraxial_trace(system, kLineD), o), SceneError);
}

}  // namespace
}  // namespace lenslab
