// Spot diagrams per field and wavelength (spot_diagrams.h):
// - the hexapolar grid of R rings holds 1 + 3R(R + 1) rays (1 + 6 + 12 + ... + 6R);
// - a plano-hyperbolic lens (k = -n², the Cartesian oval of a point at infinity: Hecht,
//   Optics, 5th ed., section 5.2.1) images the axial point perfectly: RMS radius zero;
// - pure third-order spherical aberration at the paraxial focus: each ray lands at
//   ε = σ_I ρ³ radially (σ_I = S_I / (2 n'u'), Welford, Aberrations of Optical Systems, 1986,
//   section 8.3), so the spot's centroid is the axis, its geometric radius |σ_I| (the rim)
//   and its RMS radius |σ_I| sqrt(<ρ⁶>): 1/2 |σ_I| for a continuously filled pupil
//   (<ρ⁶> = ∫ρ⁶ 2ρ dρ = 1/4), and on the hexapolar grid, ring k of R carrying 6k rays at
//   ρ = k/R, <ρ⁶> = 6 Σ k⁷ / (R⁶ (1 + 3R(R + 1)));
// - off the axis at a small aperture and field, the spot of the Sasian triplet is the
//   Seidel polynomial evaluated on the same grid (Welford 8.3): relative to the chief ray
//   ε_x = σ_I ρ² px + 2 σ_II px py + (σ_III + σ_IV) px,
//   ε_y = σ_I ρ² py + σ_II (ρ² + 2 py²) + (3 σ_III + σ_IV) py;
//   in particular the centroid sits 2 σ_II <ρ²> from the chief ray (coma's offset);
// - fields ±θ give mirror-image spots; the Airy radius is 1.22 λ N_w with the triplet's
//   published F-number (rayoptics' page: 4.0001 at infinity, where N_w = N).

#include <gtest/gtest.h>

#include <cmath>

#include "../lens_scene_builder.h"
#include "../sasian_triplet.h"
#include "analysis/aberrations/seidel.h"
#include "analysis/aberrations/spot_diagrams.h"
#include "analysis/figures/field_figures.h"
#include "analysis/report/spot_report.h"

namespace lenslab {
namespace {

using test::lens_scene;
using test::sphere;

FirstOrder spots_first_order(const OpticalSystem& system, const FirstOrderOptions& o) {
    return first_order(system, paraxial_trace(system, o.wavelength_nm), o);
}

double hexapolar_mean_rho_power(int rings, int power) {
    double sum = 0;
    for (int k = 1; k <= rings; ++k) sum += 6.0 * k * std::pow(double(k) / rings, power);
    return sum / (1 + 3 * rings * (rings + 1));
}

TEST(SpotDiagrams, HexapolarRayCounts) {
    const OpticalSystem system = test::sasian_triplet();
    const FirstOrder f = spots_first_order(system, test::sasian_options());
    for (int rings : {1, 3, 6}) {
        int sum = 1;
        for (int k = 1; k <= rings; ++k) sum += 6 * k;
        SpotOptions o;
        o.rings = rings;
        const SpotDiagrams d = spot_diagrams(system, f, o);
        EXPECT_EQ(d.rays_per_beam, sum);
        EXPECT_EQ(d.fields[0].spots[0].rays, sum);
        EXPECT_EQ(d.fields[0].spots[0].vignetted, 0);
        EXPECT_EQ(static_cast<int>(hexapolar_pupil(rings).size()), sum);
    }
}

TEST(SpotDiagrams, PlanoHyperbolicLensFocusesTheAxialPoint) {
    const double n = 1.5;
    std::ostringstream back;
    back.precision(17);
    back << R"({"shape": "conic", "radius": -30, "k": )" << -n * n << "}";
    const OpticalSystem system =
        build_optical_system(lens_scene({{"oval", 0.0, 5.0, 20.0, sphere(0), back.str()}}));
    FirstOrderOptions o;
    o.epd = 12.0;
    const FirstOrder f = spots_first_order(system, o);
    const SpotDiagrams d = spot_diagrams(system, f, {});
    const WavelengthSpot& s = d.fields[0].spots[0];
    EXPECT_EQ(s.rays, 127);
    EXPECT_LT(s.spot.rms_radius, 1e-9 * f.efl);
    EXPECT_LT(s.spot.geometric_radius, 1e-9 * f.efl);
    EXPECT_LT(d.fields[0].polychromatic.rms_radius, 1e-9 * f.efl);
}

TEST(SpotDiagrams, ThirdOrderSphericalAberrationOnTheAxis) {
    // A slow plano-convex lens (F/25), curved side first, stop at the lens.
    const OpticalSystem system = build_optical_system(
        lens_scene({{"pcx", 0.0, 4.0, 30.0, sphere(50.0), sphere(0), test::glass("N-BK7")}}));
    FirstOrderOptions o;
    o.epd = 4.0;
    const FirstOrder f = spots_first_order(system, o);
    const double sigma = seidel_sums(system, f, kLineF, kLineC).transverse.spherical;
    ASSERT_GT(std::abs(sigma), 1e-4);
    for (int rings : {3, 6}) {
        SpotOptions so;
        so.rings = rings;
        const WavelengthSpot s = spot_diagrams(system, f, so).fields[0].spots[0];
        EXPECT_NEAR(s.spot.centroid_x, 0.0, 1e-12);
        EXPECT_NEAR(s.spot.centroid_y, 0.0, 1e-12);
        EXPECT_NEAR(s.spot.geometric_radius, std::abs(sigma), 0.02 * std::abs(sigma));
        const double rms = std::abs(sigma) * std::sqrt(hexapolar_mean_rho_power(rings, 6));
        EXPECT_NEAR(s.spot.rms_radius, rms, 0.02 * rms);
    }
    // Many rings approach the filled pupil's |σ_I| / 2.
    SpotOptions fine;
    fine.rings = 60;
    const double rms = spot_diagrams(system, f, fine).fields[0].spots[0].spot.rms_radius;
    EXPECT_NEAR(rms, 0.5 * std::abs(sigma), 0.04 * std::abs(sigma));
}

TEST(SpotDiagrams, SmallApertureSpotIsTheSeidelPolynomial) {
    const OpticalSystem system = test::sasian_triplet();
    const test::SasianThirdOrder third = test::sasian_third_order(system);
    const FirstOrder& f = third.first_order;
    const SeidelTransverse& t = third.transverse;
    const double s1 = t.spherical, s2 = t.sagittal_coma, s34 = t.sagittal_field,
                 s34t = t.tangential_field;
    SpotOptions so;
    so.fields = {test::kSasianSmallField};
    const WavelengthSpot s = spot_diagrams(system, f, so).fields[0].spots[0];
    ASSERT_TRUE(s.chief.has_value());
    // The polynomial's hits relative to the chief ray, on the same grid.
    double mx = 0, my = 0, m2 = 0;
    const std::vector<PupilPoint> grid = hexapolar_pupil(so.rings);
    for (const PupilPoint& q : grid) {
        const double rho2 = q.x * q.x + q.y * q.y;
        const double ex = s1 * rho2 * q.x + 2 * s2 * q.x * q.y + s34 * q.x;
        const double ey = s1 * rho2 * q.y + s2 * (rho2 + 2 * q.y * q.y) + s34t * q.y;
        mx += ex;
        my += ey;
        m2 += ex * ex + ey * ey;
    }
    mx /= grid.size();
    my /= grid.size();
    const double rms = std::sqrt(m2 / grid.size() - mx * mx - my * my);
    EXPECT_NEAR(my, 2 * s2 * hexapolar_mean_rho_power(so.rings, 2), 1e-12 * std::abs(s2));
    EXPECT_NEAR(s.spot.centroid_y - s.chief->y, my, 0.02 * std::abs(my));
    EXPECT_NEAR(s.spot.centroid_x - s.chief->x, 0.0, 1e-12);
    EXPECT_NEAR(s.spot.rms_radius, rms, 0.02 * rms);
}

TEST(SpotDiagrams, OppositeFieldsGiveMirrorImageSpots) {
    const OpticalSystem system = test::sasian_triplet();
    const FirstOrder f = spots_first_order(system, test::sasian_options());
    SpotOptions o;
    o.fields = {14.0, -14.0};
    o.wavelengths = {kLineF, kLineD, kLineC};
    const SpotDiagrams d = spot_diagrams(system, f, o);
    for (size_t i = 0; i < o.wavelengths.size(); ++i) {
        const WavelengthSpot &up = d.fields[0].spots[i], &down = d.fields[1].spots[i];
        EXPECT_GT(up.spot.centroid_y, 1.0);
        EXPECT_NEAR(up.spot.centroid_y, -down.spot.centroid_y, 1e-9);
        EXPECT_NEAR(up.spot.centroid_x, down.spot.centroid_x, 1e-9);
        EXPECT_NEAR(up.spot.rms_radius, down.spot.rms_radius, 1e-9);
        EXPECT_NEAR(up.spot.geometric_radius, down.spot.geometric_radius, 1e-9);
        EXPECT_NEAR(up.chief->y, -down.chief->y, 1e-9);
        EXPECT_EQ(up.vignetted, down.vignetted);
    }
    EXPECT_NEAR(d.fields[0].polychromatic.rms_radius, d.fields[1].polychromatic.rms_radius, 1e-9);
}

TEST(SpotDiagrams, AiryRadiusFromTheWorkingFNumber) {
    const OpticalSystem system = test::sasian_triplet();
    const FirstOrder f = spots_first_order(system, test::sasian_options());
    SpotOptions o;
    o.wavelengths = {kLineF, kLineD};
    o.weights = {1.0, 3.0};
    const SpotDiagrams d = spot_diagrams(system, f, o);
    // The page's F/4.0001 at 587.5618 nm; lengths in mm.
    EXPECT_NEAR(d.fields[0].airy_radius, 1.22 * 587.5618e-6 * 4.0001, 1e-7);
    EXPECT_NEAR(d.fields[0].spots[0].airy_radius, 1.22 * kLineF * 1e-6 * 4.0001, 1e-7);
    EXPECT_EQ(d.weights, o.weights);
    EXPECT_EQ(d.fields[0].polychromatic.rays, 2 * 127);
}

TEST(SpotDiagrams, FigureDrawsEveryRayThatPassed) {
    const OpticalSystem system = test::sasian_triplet();
    const FirstOrder f = spots_first_order(system, test::sasian_options());
    SpotOptions o;
    o.fields = {0.0, 20.0};
    o.wavelengths = {kLineF, kLineC};
    o.rings = 3;
    const SpotDiagrams d = spot_diagrams(system, f, o);
    size_t passed = 0;
    for (const FieldSpots& field : d.fields)
        passed += field.polychromatic.rays - field.polychromatic.lost;
    ASSERT_GT(d.fields[1].polychromatic.lost, 0);  // the 20 degree beam is vignetted
    const RayDiagram figure = spot_diagram_figure(d, "mm", "deg");
    EXPECT_EQ(figure.dots.size(), passed);
    EXPECT_EQ(figure.legend.size(), 2u);
}

TEST(SpotDiagrams, JsonListsEveryFieldAndWavelength) {
    const OpticalSystem system = test::sasian_triplet();
    const FirstOrder f = spots_first_order(system, test::sasian_options());
    SpotOptions o;
    o.fields = {0.0, 20.0};
    o.wavelengths = {kLineF, kLineD, kLineC};
    o.rings = 2;
    const nlohmann::ordered_json j = spots_json(system, spot_diagrams(system, f, o));
    ASSERT_EQ(j["per_wavelength"].size(), 6u);  // fields in order, wavelengths within each
    EXPECT_EQ(j["per_wavelength"][4]["field"], 20.0);
    EXPECT_EQ(j["per_wavelength"][4]["wavelength"], kLineD);
    EXPECT_EQ(j["per_wavelength"][4]["rays"], 19);
    ASSERT_EQ(j["polychromatic"].size(), 2u);
    EXPECT_EQ(j["polychromatic"][1]["rays"], 57);
    EXPECT_EQ(j["weights"], nlohmann::ordered_json::array({1.0, 1.0, 1.0}));
    EXPECT_NEAR(j["image_position"].get<double>(), f.image_position, 1e-12);
    EXPECT_EQ(j["reference"], "centroid");
}

}  // namespace
}  // namespace lenslab
