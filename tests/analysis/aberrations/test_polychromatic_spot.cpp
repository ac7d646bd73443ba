// The polychromatic RMS spot (polychromatic_spot.h):
// - a plano-hyperbolic lens (flat face first, conic k = -n² behind: the Cartesian oval of a
//   point at infinity, Hecht, Optics, 5th ed., section 5.2.1) focuses the axial beam to a
//   point: RMS radius zero at its focus;
// - defocused by dz it gives a disc of radius dz tan(u'), u' the rim ray's angle, sampled on
//   the hexapolar grid: ring k of R carries 6k rays at radius k/R, so the mean square radius
//   over the 1 + 3R(R + 1) rays is (6 / R²) (R(R + 1) / 2)² / (1 + 3R(R + 1)) times the rim's
//   square (0.5787 for R = 6, against 1/2 for a continuously filled disc: the convention of
//   Zemax's hexapolar spot diagrams);
// - one wavelength alone, or two with one of them at weight 0, gives spot_at's RMS radius;
//   two together add their centroids' spread (law of total variance).

#include <gtest/gtest.h>

#include <cmath>

#include "../lens_scene_builder.h"
#include "analysis/aberrations/polychromatic_spot.h"
#include "analysis/system/field_beam.h"

namespace lenslab {
namespace {

using test::lens_scene;
using test::sphere;

OpticalSystem plano_hyperbolic(const std::string& material) {
    const double n = 1.5;
    std::ostringstream back;
    back.precision(17);
    back << R"({"shape": "conic", "radius": -30, "k": )" << -n * n << "}";
    return build_optical_system(
        lens_scene({{"oval", 0.0, 5.0, 20.0, sphere(0), back.str(), material}}));
}

FirstOrder spot_first_order(const OpticalSystem& system, double epd) {
    FirstOrderOptions o;
    o.epd = epd;
    return first_order(system, paraxial_trace(system, o.wavelength_nm), o);
}

TEST(PolychromaticSpot, PerfectFocusAndDefocusedDisc) {
    const OpticalSystem system = plano_hyperbolic(R"({"transparency": 1, "ior": 1.5})");
    const FirstOrder f = spot_first_order(system, 10.0);
    const double focus = system.last_vertex() + f.image_position;
    const int rings = 6;
    const PolychromaticSpot sharp =
        polychromatic_rms_spot(system, f, 0.0, {kLineD}, {}, rings, focus);
    EXPECT_EQ(sharp.rays, 127);
    EXPECT_EQ(sharp.lost, 0);
    EXPECT_LT(sharp.rms_radius, 1e-9 * f.efl);

    const double dz = 0.5;
    const FieldBeam beam = trace_field_beam(system, f, 0.0, kLineD, rings);
    const ExitRay& rim = beam.rays.back();  // the last ray of the outer ring
    const double rim_radius = dz * std::hypot(rim.direction.x, rim.direction.y) / rim.direction.z;
    const double r = rings,
                 ratio = 6.0 / (r * r) * std::pow(r * (r + 1) / 2, 2) / (1 + 3 * r * (r + 1));
    const PolychromaticSpot blurred =
        polychromatic_rms_spot(system, f, 0.0, {kLineD}, {}, rings, focus + dz);
    EXPECT_NEAR(blurred.rms_radius, rim_radius * std::sqrt(ratio), 0.01 * rim_radius);
}

TEST(PolychromaticSpot, WeightsSelectTheWavelengths) {
    const OpticalSystem system = plano_hyperbolic(R"({"transparency": 1, "glass": "N-BK7"})");
    const FirstOrder f = spot_first_order(system, 10.0);
    const double plane = system.last_vertex() + f.image_position + 0.2;
    for (const double nm : {kLineF, kLineC}) {
        const FieldBeam beam = trace_field_beam(system, f, 5.0, nm, 4);
        const double alone = spot_at(beam.rays, plane).rms_radius;
        EXPECT_NEAR(polychromatic_rms_spot(system, f, 5.0, {nm}, {}, 4, plane).rms_radius, alone,
                    1e-12);
        const std::vector<double> weights =
            nm == kLineF ? std::vector<double>{1.0, 0.0} : std::vector<double>{0.0, 1.0};
        EXPECT_NEAR(
            polychromatic_rms_spot(system, f, 5.0, {kLineF, kLineC}, weights, 4, plane).rms_radius,
            alone, 1e-12);
    }
    // Both together, equal ray counts: by the law of total variance the mean square radius
    // is the mean of the two plus the square of half the distance between their centroids
    // (lateral colour).
    const auto one = [&](double nm) {
        return polychromatic_rms_spot(system, f, 5.0, {nm}, {}, 4, plane);
    };
    const PolychromaticSpot blue = one(kLineF), red = one(kLineC);
    const double apart =
        std::hypot(blue.centroid_x - red.centroid_x, blue.centroid_y - red.centroid_y);
    ASSERT_GT(apart, 1e-4);
    const double both =
        polychromatic_rms_spot(system, f, 5.0, {kLineF, kLineC}, {}, 4, plane).rms_radius;
    EXPECT_NEAR(both * both,
                0.5 * (std::pow(blue.rms_radius, 2) + std::pow(red.rms_radius, 2)) +
                    std::pow(0.5 * apart, 2),
                1e-12);
}

}  // namespace
}  // namespace lenslab
