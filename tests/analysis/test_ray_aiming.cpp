// Ray aiming and the aimed field beam:
// - aimed rays of the Cooke triplet (sasian_triplet.h) cross its stop, inside the lens, where
//   they were aimed, at the full 20 degree field where the real entrance pupil is shifted
//   against the paraxial one, and from a finite object;
// - at a small aperture and field, where third order rules, the aimed rays' transverse
//   aberrations in the paraxial image plane (relative to the aimed chief ray) are the
//   polynomial of the Seidel sums (Welford, Aberrations of Optical Systems, 1986, section
//   8.3: tangential fan σ_I ρ³ + 3 σ_II ρ² + (3 σ_III + σ_IV) ρ, sagittal fan x: σ_I ρ³ +
//   (σ_III + σ_IV) ρ and y: σ_II ρ², σ = S / (2 n'u') at the edge of pupil and field).

#include <gtest/gtest.h>

#include <cmath>

#include "analysis/field_beam.h"
#include "analysis/ray_aiming.h"
#include "analysis/seidel.h"
#include "sasian_triplet.h"

namespace lenslab {
namespace {

FirstOrder aiming_first_order(const OpticalSystem& system, const FirstOrderOptions& o) {
    return first_order(system, paraxial_trace(system, o.wavelength_nm), o);
}

void expect_aimed_at_stop(const OpticalSystem& system, const FirstOrder& f, double field) {
    const RayAimer aimer(system, f, field, f.wavelength_nm);
    const double r = f.stop_semi_diameter;
    for (const PupilPoint q : {PupilPoint{0, 0}, PupilPoint{0, 1}, PupilPoint{0, -1},
                               PupilPoint{1, 0}, PupilPoint{-0.6, 0.7}}) {
        SCOPED_TRACE(::testing::Message() << "px " << q.x << " py " << q.y);
        const auto start = aimer.aim(q.x, q.y);
        ASSERT_TRUE(start.has_value());
        const RealRay ray = trace_real_ray(system, *start, f.wavelength_nm, Rims::Ignore);
        ASSERT_EQ(ray.fate, RayFate::Passed);
        const Vec3& at_stop = ray.points[f.stop + 1];
        EXPECT_NEAR(at_stop.x, q.x * r, 1e-9);
        EXPECT_NEAR(at_stop.y, q.y * r, 1e-9);
    }
}

TEST(RayAiming, FullFieldRaysCrossTheStopWhereAimed) {
    const OpticalSystem system = test::sasian_triplet();
    const FirstOrder f = aiming_first_order(system, test::sasian_options());
    expect_aimed_at_stop(system, f, 20.0);
    expect_aimed_at_stop(system, f, -14.0);
}

TEST(RayAiming, FiniteObjectRaysCrossTheStopWhereAimed) {
    const OpticalSystem system = test::sasian_triplet();
    FirstOrderOptions o = test::sasian_options();
    o.object_distance = 300.0;
    o.fields = {40.0};  // object height
    expect_aimed_at_stop(system, aiming_first_order(system, o), 40.0);
}

TEST(RayAiming, SmallApertureFansFollowTheSeidelPolynomial) {
    const OpticalSystem system = test::sasian_triplet();
    const test::SasianThirdOrder third = test::sasian_third_order(system);
    const FirstOrder& f = third.first_order;
    const SeidelTransverse& t = third.transverse;
    const RayAimer aimer(system, f, test::kSasianSmallField, f.wavelength_nm);
    const double z_image = system.last_vertex() + f.image_position;
    const auto image_point = [&](double px, double py) {
        const auto ray = aimer.trace(px, py);
        EXPECT_TRUE(ray && ray->fate == RayFate::Passed);
        return at_plane(ray->exit_point(), ray->direction, z_image);
    };
    const Vec3 chief = image_point(0, 0);
    for (double rho : {1.0, -1.0, 0.5}) {
        SCOPED_TRACE(::testing::Message() << "rho " << rho);
        const double tangential = t.spherical * rho * rho * rho + t.tangential_coma * rho * rho +
                                  t.tangential_field * rho;
        const double ey = image_point(0, rho).y - chief.y;
        EXPECT_NEAR(ey, tangential, 0.02 * std::abs(tangential));
        const Vec3 s = image_point(rho, 0);
        const double sagittal_x = t.spherical * rho * rho * rho + t.sagittal_field * rho;
        EXPECT_NEAR(s.x - chief.x, sagittal_x, 0.02 * std::abs(sagittal_x));
        EXPECT_NEAR(s.y - chief.y, t.sagittal_coma * rho * rho, 0.02 * std::abs(t.sagittal_coma));
    }
}

TEST(FieldBeam, FillsTheStopAndCountsTheVignettedRays) {
    const OpticalSystem system = test::sasian_triplet();
    const FirstOrder f = aiming_first_order(system, test::sasian_options());
    // 1 + 6 + 12 + 18 + 24 rays. On the axis all pass; at 20 degrees the rim of L2's back
    // face (4.8 across the axis) cuts the outer rays of the tilted beam, not the chief ray.
    const FieldBeam axial = trace_field_beam(system, f, 0.0, kLineF, 4);
    EXPECT_EQ(axial.rays.size(), 61u);
    EXPECT_EQ(axial.lost, 0);
    const FieldBeam edge = trace_field_beam(system, f, 20.0, kLineF, 4);
    EXPECT_EQ(edge.rays.size() + edge.lost, 61u);
    EXPECT_GT(edge.lost, 0);
    EXPECT_LT(edge.lost, 24);
    ASSERT_TRUE(edge.chief.has_value());
    EXPECT_EQ(edge.chief->point.y, edge.rays.front().point.y);
}

}  // namespace
}  // namespace lenslab
