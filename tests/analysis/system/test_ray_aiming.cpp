// Ray aiming and the aimed field beam:
// - aimed rays of the Cooke triplet (sasian_triplet.h) cross its stop, inside the lens, where
//   they were aimed, at the full 20 degree field where the real entrance pupil is shifted
//   against the paraxial one, and from a finite object;
// - at a small aperture and field, where third order rules, the aimed rays' transverse
//   aberrations in the paraxial image plane (relative to the aimed chief ray) are the
//   polynomial of the Seidel sums (Welford, Aberrations of Optical Systems, 1986, section
//   8.3: tangential fan σ_I ρ³ + 3 σ_II ρ² + (3 σ_III + σ_IV) ρ, sagittal fan x: σ_I ρ³ +
//   (σ_III + σ_IV) ρ and y: σ_II ρ², σ = S / (2 n'u') at the edge of pupil and field);
// - paraxial aiming (Zemax's "ray aiming off") sends each ray, in object space, through its
//   point of the paraxial entrance pupil: there it lands exactly, and at the stop it misses
//   the aimed point by the pupil's aberration, which grows with the field.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../sasian_triplet.h"
#include "analysis/aberrations/seidel.h"
#include "analysis/system/field_beam.h"
#include "analysis/system/ray_aiming.h"

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

TEST(RayAiming, ParaxialAimingGoesThroughTheParaxialEntrancePupil) {
    const OpticalSystem system = test::sasian_triplet();
    FirstOrderOptions o = test::sasian_options();
    o.ray_aiming = RayAiming::Paraxial;
    const FirstOrder f = aiming_first_order(system, o);
    ASSERT_EQ(f.ray_aiming, RayAiming::Paraxial);
    const double z_ep = f.entrance_pupil.position, r_ep = 0.5 * f.entrance_pupil.diameter;
    double miss_on_axis = 0, miss_at_20 = 0;
    for (const double field : {0.0, 20.0}) {
        const RayAimer paraxial(system, f, field, f.wavelength_nm);
        for (const PupilPoint q : {PupilPoint{0, 0}, PupilPoint{0, 1}, PupilPoint{1, 0}}) {
            SCOPED_TRACE(::testing::Message() << field << " deg, px " << q.x << " py " << q.y);
            const auto start = paraxial.aim(q.x, q.y);
            ASSERT_TRUE(start.has_value());
            const Vec3 at_pupil = at_plane(start->origin, start->direction, z_ep);
            EXPECT_NEAR(at_pupil.x, q.x * r_ep, 1e-12);
            EXPECT_NEAR(at_pupil.y, q.y * r_ep, 1e-12);
            const RealRay ray = trace_real_ray(system, *start, f.wavelength_nm, Rims::Ignore);
            ASSERT_EQ(ray.fate, RayFate::Passed);
            const Vec3& at_stop = ray.points[f.stop + 1];
            const double miss = std::hypot(at_stop.x - q.x * f.stop_semi_diameter,
                                           at_stop.y - q.y * f.stop_semi_diameter);
            (field == 0.0 ? miss_on_axis : miss_at_20) =
                std::max(field == 0.0 ? miss_on_axis : miss_at_20, miss);
        }
    }
    // Real aiming lands on the stop to 1e-9 (above); paraxial aiming misses it by the pupil's
    // aberration (measured: 0.126 on the axis, 0.250 at 20 degrees), more off the axis, where the
    // real entrance pupil is shifted too.
    std::printf("paraxial aiming misses the stop by %.4f on the axis, %.4f at 20 degrees\n",
                miss_on_axis, miss_at_20);
    EXPECT_GT(miss_on_axis, 1e-3);
    EXPECT_GT(miss_at_20, miss_on_axis);
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
