// Seidel sums against published figures and closed forms:
// - the Cooke triplet of sasian_triplet.h against the third-order table the rayoptics page
//   prints (`compute_third_order`, six decimals) and its transverse forms;
// - a thin singlet against Welford's thin-lens formulas (Aberrations of Optical Systems,
//   1986, ch. 8, the thin lens in air with the stop at it: shape factor
//   B = (c1 + c2) / (c1 - c2), conjugate factor C = (u1 + u2') / (u1 - u2'), power K);
// - distortion of a symmetric system at unit magnification with the stop at its centre:
//   zero, paraxially and for the real chief ray;
// - a plano-hyperbolic lens (flat face first, conic k = -n² behind): the conic's term
//   cancels the sphere's spherical aberration, as its perfect axial focus requires;
// - a surface typed as a sag formula gives the sums of the closed form it equals: the
//   paraboloid r^2/80 those of the conic of vertex radius 40 with k = -1, a formula with an
//   r^4 term those of the even asphere with the same A4 (the bench reads every surface
//   through its vertex Taylor series, geometry/lens/lens_surface.h).

#include <gtest/gtest.h>

#include <cmath>

#include "../lens_scene_builder.h"
#include "../sasian_triplet.h"
#include "analysis/aberrations/seidel.h"
#include "analysis/system/real_chief_ray.h"

namespace lenslab {
namespace {

using test::glass;
using test::lens_scene;
using test::LensSpec;
using test::sphere;

FirstOrder seidel_first_order(const OpticalSystem& system, FirstOrderOptions o) {
    return first_order(system, paraxial_trace(system, o.wavelength_nm), o);
}

TEST(SeidelCookeTriplet, SumsMatchRayopticsTable) {
    const OpticalSystem system = test::sasian_triplet();
    const Seidel s =
        seidel_sums(system, seidel_first_order(system, test::sasian_options()), kLineF, kLineC);
    // The page's table: S-I .. S-V for surfaces 1-6, then the sum.
    const double table[7][5] = {
        {0.027654, 0.019379, 0.013581, 0.089174, 0.072010},
        {0.022082, -0.059501, 0.160327, -0.000288, -0.431229},
        {-0.105156, 0.137692, -0.180295, -0.085097, 0.347506},
        {-0.045358, -0.076796, -0.130024, -0.095046, -0.381069},
        {0.007942, 0.028382, 0.101431, 0.024373, 0.449596},
        {0.103810, -0.050068, 0.024148, 0.103180, -0.061411},
        {0.010973, -0.000912, -0.010832, 0.036297, -0.004597},
    };
    ASSERT_EQ(s.surfaces.size(), 6u);
    for (int i = 0; i < 7; ++i) {
        SCOPED_TRACE(i + 1);
        const SeidelSums& v = i < 6 ? s.surfaces[i] : s.total;
        // Six decimals printed: half a unit of the last, and as much again for the glass
        // indices (the same Schott Sellmeier formulas, evaluated in another program).
        const double tol = 1e-6;
        EXPECT_NEAR(v.spherical, table[i][0], tol);
        EXPECT_NEAR(v.coma, table[i][1], tol);
        EXPECT_NEAR(v.astigmatism, table[i][2], tol);
        EXPECT_NEAR(v.petzval, table[i][3], tol);
        EXPECT_NEAR(v.distortion, table[i][4], tol);
    }
    // seidel_to_transverse_aberration on the page: TSA, TCO, TAS, SAS, PTB, DST.
    const SeidelTransverse& t = s.transverse;
    EXPECT_NEAR(t.spherical, -0.043893, 1e-5);
    EXPECT_NEAR(t.tangential_coma, 0.010944, 1e-5);
    EXPECT_NEAR(t.tangential_field, -0.015198, 1e-5);
    EXPECT_NEAR(t.sagittal_field, -0.101860, 1e-5);
    EXPECT_NEAR(t.petzval, -0.145190, 1e-5);
    EXPECT_NEAR(t.distortion, 0.018387, 1e-5);
}

TEST(SeidelCookeTriplet, RealDistortionTendsToTheThirdOrderAtSmallFields) {
    // Distortion is third order in the field: at 1 degree the real chief ray's distortion
    // and the Seidel term S_V / (2 n'u') over the image height agree but for the
    // fifth-order part, which grows as the field squared (0.6% of it at 2 degrees here):
    // within 1%. At 20 degrees they differ by a factor of ten; the sums are not the lens.
    const OpticalSystem system = test::sasian_triplet();
    const FirstOrder f = seidel_first_order(system, test::sasian_options(1.0));
    const double third = seidel_sums(system, f, kLineF, kLineC).transverse.distortion;
    const std::optional<RealChiefRay> real = trace_real_chief_ray(system, f);
    ASSERT_TRUE(real.has_value());
    const double third_relative = third / f.image_height;
    EXPECT_NEAR(real->distortion, third_relative, 0.01 * std::abs(third_relative));
}

TEST(SeidelThinLens, MatchesWelfordsThinLensFormulas) {
    // A singlet of N-BK7, R1 = 50, R2 = -80, 1 mm across and 5 µm thick at the centre, beam
    // 1 mm across at infinity, 1 degree field, stop at the lens (its first surface). The
    // thin-lens formulas drop the thickness: the marginal ray's height changes across the
    // lens by t K / n ≈ 6e-5 of itself, and the chief ray reaches the back surface at
    // t ū / n ≈ 1.2e-4 of the marginal height, which is what S_V = 0 and C_II = 0 neglect
    // (S_V then comes to about twice that of S_III). The tolerance, 1e-3 relative, is above
    // these and below the size of any term.
    const double r1 = 50.0, r2 = -80.0, t = 0.005;
    const OpticalSystem system = build_optical_system(
        lens_scene({{"thin", 0.0, t, 1.0, sphere(r1), sphere(r2), glass("N-BK7")}}));
    FirstOrderOptions o;
    o.epd = 1.0;
    o.fields = {1.0};
    const FirstOrder f = seidel_first_order(system, o);
    const Seidel s = seidel_sums(system, f, kLineF, kLineC);

    const IndexModel& index = *system.elements[0].index;
    const double n = index.n(kLineD);
    const double v = (n - 1.0) / (index.n(kLineF) - index.n(kLineC));
    const double c1 = 1.0 / r1, c2 = 1.0 / r2;
    const double k = (n - 1.0) * (c1 - c2);
    const double b = (c1 + c2) / (c1 - c2);
    const double c = -1.0;  // u1 = 0, u2' = -y K: object at infinity
    const double y = 0.5;
    // Welford writes H = n u η at the object (the marginal slope times the object height),
    // the opposite sign of ours, n (ū y - u ȳ): only S_II, odd in H, shows it.
    const double h_welford = -f.lagrange_invariant;
    const double s1 = std::pow(y, 4) * std::pow(k, 3) / 4.0 *
                      (std::pow(n / (n - 1.0), 2) + (n + 2.0) / (n * std::pow(n - 1.0, 2)) * b * b +
                       4.0 * (n + 1.0) / (n * (n - 1.0)) * b * c + (3.0 * n + 2.0) / n * c * c);
    const double s2 = -y * y * k * k * h_welford / 2.0 *
                      ((n + 1.0) / (n * (n - 1.0)) * b + (2.0 * n + 1.0) / n * c);
    const double s3 = h_welford * h_welford * k;
    const double s4 = h_welford * h_welford * k / n;
    const double c1_sum = y * y * k / v;

    const double rel = 1e-3;
    EXPECT_NEAR(s.total.spherical, s1, rel * std::abs(s1));
    EXPECT_NEAR(s.total.coma, s2, rel * std::abs(s2));
    EXPECT_NEAR(s.total.astigmatism, s3, rel * std::abs(s3));
    EXPECT_NEAR(s.total.petzval, s4, rel * std::abs(s4));
    EXPECT_NEAR(s.total.distortion, 0.0, rel * std::abs(s3));  // S_V = 0 with the stop at it
    EXPECT_NEAR(s.total.axial_colour, c1_sum, rel * c1_sum);
    EXPECT_NEAR(s.total.lateral_colour, 0.0, rel * c1_sum);  // C_II = 0 likewise
    // Longitudinal colour -C_I / (n'u'²) is the paraxial focal shift between F and C to
    // first order in the dispersion, δn / (n - 1) ≈ 1/64 here: within 3%.
    const double shift = paraxial_trace(system, kLineF).bfl - paraxial_trace(system, kLineC).bfl;
    EXPECT_NEAR(s.transverse.longitudinal_axial_colour, shift, 0.03 * std::abs(shift));
}

// Two identical plano-convex lenses of one glass, flat faces together: a system symmetric
// about the cemented plane. With the stop there and the object where the image is its
// mirror (magnification -1), every ray through the stop's centre leaves as the mirror image
// of how it came, so the image height is exactly minus the object height: no distortion, in
// third order (the symmetry principle, Welford ch. 8: S_II, S_V, C_II vanish) and for the
// real ray.
OpticalSystem symmetric_pair() {
    return build_optical_system(lens_scene({
        {"front", 0.0, 4.0, 16.0, sphere(30.0), sphere(0), glass("N-BK7")},
        {"back", 4.0, 4.0, 16.0, sphere(0), sphere(-30.0), glass("N-BK7")},
    }));
}

TEST(SeidelDistortion, SymmetricSystemWithTheStopAtItsCentreHasNone) {
    const OpticalSystem system = symmetric_pair();
    ASSERT_EQ(system.surfaces.size(), 3u);  // the flat faces are one interface
    const ParaxialResult p = paraxial_trace(system, kLineD);
    FirstOrderOptions o;
    o.stop = 1;
    o.epd = 4.0;
    o.object_distance = 2.0 * p.efl - p.z_front_principal;  // 2f in front of H
    o.fields = {5.0};
    const FirstOrder f = seidel_first_order(system, o);
    ASSERT_TRUE(f.magnification.has_value());
    EXPECT_NEAR(*f.magnification, -1.0, 1e-12);
    const Seidel s = seidel_sums(system, f, kLineF, kLineC);
    const double scale = std::abs(s.surfaces[0].distortion);
    ASSERT_GT(scale, 1e-4);  // each outer surface distorts; they cancel
    EXPECT_NEAR(s.total.distortion, 0.0, 1e-12 * scale);
    EXPECT_NEAR(s.total.coma, 0.0, 1e-12 * std::abs(s.surfaces[0].coma));
    EXPECT_NEAR(s.total.lateral_colour, 0.0, 1e-12 * std::abs(s.surfaces[0].lateral_colour));

    const std::optional<RealChiefRay> real = trace_real_chief_ray(system, f);
    ASSERT_TRUE(real.has_value());
    EXPECT_NEAR(real->image_height, -5.0, 1e-9);
    EXPECT_NEAR(real->distortion, 0.0, 1e-9);

    // The stop moved to the first surface breaks the symmetry: distortion appears, in both.
    o.stop = 0;
    const FirstOrder moved = seidel_first_order(system, o);
    EXPECT_GT(std::abs(seidel_sums(system, moved, kLineF, kLineC).total.distortion), 1e-3 * scale);
    const std::optional<RealChiefRay> moved_real = trace_real_chief_ray(system, moved);
    ASSERT_TRUE(moved_real.has_value());
    EXPECT_GT(std::abs(moved_real->distortion), 1e-5);
}

TEST(SeidelConic, PlanoHyperbolicLensHasNoSphericalAberration) {
    // Flat face first (collimated light inside), then a hyperboloid of conic constant
    // -n²: the Cartesian oval for a point at infinity in glass. Its conic term must cancel
    // the sphere's S_I; with k = 0 (a sphere) S_I stays.
    const double n = 1.5;
    const auto lens = [&](double k) {
        std::ostringstream back;
        back.precision(17);
        back << R"({"shape": "conic", "radius": -30, "k": )" << k << "}";
        return build_optical_system(
            lens_scene({{"hyperbolic", 0.0, 5.0, 20.0, sphere(0), back.str(),
                         R"({"transparency": 1, "ior": 1.5})"}}));
    };
    FirstOrderOptions o;
    o.epd = 10.0;
    const OpticalSystem sphere_lens = lens(0.0);
    const double s1_sphere =
        seidel_sums(sphere_lens, seidel_first_order(sphere_lens, o), kLineF, kLineC)
            .total.spherical;
    ASSERT_GT(std::abs(s1_sphere), 1e-3);
    const OpticalSystem oval = lens(-n * n);
    const double s1_oval =
        seidel_sums(oval, seidel_first_order(oval, o), kLineF, kLineC).total.spherical;
    EXPECT_NEAR(s1_oval, 0.0, 1e-12 * std::abs(s1_sphere));
}

// A plano-convex singlet whose curved face is `front`, stop at it, field 10 degrees: its
// Seidel sums.
Seidel singlet_sums(const std::string& front) {
    const OpticalSystem system = build_optical_system(
        lens_scene({{"singlet", 0.0, 6.0, 20.0, front, sphere(0), glass("N-BK7")}}));
    FirstOrderOptions o;
    o.epd = 16.0;
    o.fields = {10.0};
    return seidel_sums(system, seidel_first_order(system, o), kLineF, kLineC);
}

void expect_equal_sums(const Seidel& a, const Seidel& b, double tol) {
    EXPECT_NEAR(a.total.spherical, b.total.spherical, tol);
    EXPECT_NEAR(a.total.coma, b.total.coma, tol);
    EXPECT_NEAR(a.total.astigmatism, b.total.astigmatism, tol);
    EXPECT_NEAR(a.total.petzval, b.total.petzval, tol);
    EXPECT_NEAR(a.total.distortion, b.total.distortion, tol);
    EXPECT_NEAR(a.total.axial_colour, b.total.axial_colour, tol);
    EXPECT_NEAR(a.total.lateral_colour, b.total.lateral_colour, tol);
}

TEST(SeidelSagFormula, ParaboloidFormulaEqualsTheConic) {
    const Seidel formula = singlet_sums(R"({"shape": "sag", "formula": "r^2/80"})");
    const Seidel conic = singlet_sums(R"({"shape": "conic", "radius": 40, "k": -1})");
    expect_equal_sums(formula, conic, 1e-9);
    // The paraboloid's fourth-order term is not the sphere's: its S_I differs from the
    // sphere's by the conic term (so a formula read as its sphere would fail above).
    const Seidel sphere_sums = singlet_sums(sphere(40));
    EXPECT_GT(std::abs(sphere_sums.total.spherical - conic.total.spherical), 1e-3);
}

TEST(SeidelSagFormula, QuarticTermEqualsTheEvenAsphere) {
    const Seidel formula =
        singlet_sums(R"({"shape": "sag", "formula": "r^2/(50*(1+sqrt(1-r^2/2500))) + 2e-6*r^4"})");
    const Seidel asphere =
        singlet_sums(R"({"shape": "asphere", "radius": 50, "k": 0, "coefficients": [2e-6]})");
    expect_equal_sums(formula, asphere, 1e-9);
    EXPECT_GT(std::abs(formula.total.spherical - singlet_sums(sphere(50)).total.spherical), 1e-3);
}

}  // namespace
}  // namespace lenslab
