// Real-ray aberrations against closed forms and the equation lenses:
// - the longitudinal spherical aberration of a plano-convex lens (flat side to the beam)
//   against the exact refraction at one sphere;
// - the hyperboloid of conic constant k = -n^2 focuses to a point (Hecht, Optics, 5th ed.,
//   section 5.2.1), the sphere of the same vertex radius does not;
// - the best focus found in closed form is the minimum of the RMS spot radius;
// - a smaller second lens limits the usable aperture.

#include <gtest/gtest.h>

#include <cmath>

#include "../lens_scene_builder.h"
#include "analysis/aberrations/aberrations.h"
#include "analysis/system/real_ray.h"

namespace lenslab {
namespace {

using test::lens_scene;
using test::LensSpec;
using test::sphere;

constexpr double kN = 1.5, kR = -50.0, kThickness = 5.0, kDiameter = 25.0;
constexpr double kFocalLength = -kR / (kN - 1.0);  // 100

OpticalSystem plano_convex(const std::string& back) {
    const LensSpec l{
        "lens", 0, kThickness, kDiameter, sphere(0), back, R"({"transparency": 1, "ior": 1.5})"};
    return build_optical_system(lens_scene({l}));
}

struct Beam {
    std::vector<ExitRay> rays;
    int lost = 0;
};

Beam beam(const OpticalSystem& s, double aperture = 0.45 * kDiameter) {
    Beam b;
    b.rays = trace_collimated_beam(s, kLineD, aperture, 12, &b.lost);
    return b;
}

TEST(Aberrations, PlanoConvexLsaMatchesExactRefractionAtTheSphere) {
    // Inside the glass the ray is still parallel at height h; it meets the sphere (centre C
    // on the axis, |R| before the vertex) at incidence a, sin a = h / |R|, leaves at b,
    // sin b = n sin a, and crosses the axis |R| sin b / sin(b - a) beyond C (sine rule). The
    // paraxial limit is |R| n / (n - 1): the focus at f = 100 behind the vertex.
    const OpticalSystem s = plano_convex(sphere(kR));
    const ParaxialResult p = paraxial_trace(s, kLineD);
    ASSERT_NEAR(p.bfl, kFocalLength, 1e-9);
    const auto lsa = longitudinal_spherical_aberration(s, p, 12.5, 10);
    ASSERT_EQ(lsa.size(), 10u);
    double previous = 0;
    for (const LsaPoint& q : lsa) {
        const double a = std::asin(q.height / -kR), b = std::asin(kN * std::sin(a));
        const double exact = -kR * std::sin(b) / std::sin(b - a) - -kR * kN / (kN - 1);
        EXPECT_NEAR(q.lsa, exact, 1e-9 * kFocalLength) << "h = " << q.height;
        // Undercorrected, and growing with the height: the classic curve.
        EXPECT_LT(q.lsa, previous);
        previous = q.lsa;
    }
    // Third order: LSA grows as h^2 near the axis (the ratio at h and h/2 tends to 4).
    EXPECT_NEAR(lsa[1].lsa / lsa[0].lsa, 4.0, 0.02);
}

TEST(Aberrations, HyperboloidFocusesToAPointSphereDoesNot) {
    const std::string k = std::to_string(-kN * kN);
    const OpticalSystem hyperboloid =
        plano_convex(R"({"shape": "conic", "radius": -50, "k": )" + k + "}");
    const OpticalSystem typed = plano_convex(
        R"j({"shape": "sag", "formula": "-r^2 / (50 * (1 + sqrt(1 + 1.25 * r^2 / 2500)))"})j");
    const OpticalSystem spherical = plano_convex(sphere(kR));

    for (const OpticalSystem* s : {&hyperboloid, &typed}) {
        const ParaxialResult p = paraxial_trace(*s, kLineD);
        EXPECT_NEAR(p.efl, kFocalLength, 1e-6 * kFocalLength);
        const Beam b = beam(*s);
        EXPECT_EQ(b.lost, 0);
        const SpotDiagram at_focus = spot_at(b.rays, p.z_rear_focus);
        const SpotDiagram best = spot_at(b.rays, best_focus_z(b.rays, p.z_rear_focus));
        EXPECT_LT(at_focus.rms_radius, 1e-6 * kFocalLength);
        EXPECT_LT(best.rms_radius, 1e-6 * kFocalLength);
        EXPECT_NEAR(best.z, p.z_rear_focus, 1e-3);
    }

    const ParaxialResult p = paraxial_trace(spherical, kLineD);
    const Beam b = beam(spherical);
    const SpotDiagram at_focus = spot_at(b.rays, p.z_rear_focus);
    const SpotDiagram best = spot_at(b.rays, best_focus_z(b.rays, p.z_rear_focus));
    // The sphere's best spot is far larger, lies in front of the paraxial focus (where the
    // marginal rays cross first) and beats the paraxial focal plane.
    EXPECT_GT(best.rms_radius, 1e-4 * kFocalLength);
    EXPECT_LT(best.z, p.z_rear_focus);
    EXPECT_LT(best.rms_radius, at_focus.rms_radius);
    EXPECT_GE(best.geometric_radius, best.rms_radius);
    // On the axis the spot is centred there.
    EXPECT_NEAR(best.centroid_x, 0.0, 1e-12);
    EXPECT_NEAR(best.centroid_y, 0.0, 1e-12);
}

TEST(Aberrations, BestFocusIsTheMinimumOfTheRmsRadius) {
    const OpticalSystem s = plano_convex(sphere(kR));
    const Beam b = beam(s);
    const double z_best = best_focus_z(b.rays, 100.0);
    const double rms_best = spot_at(b.rays, z_best).rms_radius;
    for (double dz : {-0.5, -0.05, -0.005, 0.005, 0.05, 0.5}) {
        EXPECT_GT(spot_at(b.rays, z_best + dz).rms_radius, rms_best) << dz;
    }
}

TEST(Aberrations, ASmallerSecondLensLimitsTheAperture) {
    // A 25 mm lens then, 5 mm behind it, a 10 mm one: rays entering above some height miss
    // the second lens.
    const LensSpec big{"big", 0, 5, 25, sphere(100), sphere(-100)};
    const LensSpec small{"small", 10, 3, 10, sphere(50), sphere(-50)};
    const OpticalSystem s = build_optical_system(lens_scene({big, small}));
    const double h = usable_aperture_radius(s, kLineD);
    EXPECT_GT(h, 4.5);
    EXPECT_LT(h, 5.5);
    const double z0 = beam_start_z(s);
    EXPECT_EQ(trace_real_ray(s, {{0, 0.999 * h, z0}, {0, 0, 1}}, kLineD).fate, RayFate::Passed);
    const RealRay clipped = trace_real_ray(s, {{0, 1.001 * h, z0}, {0, 0, 1}}, kLineD);
    EXPECT_EQ(clipped.fate, RayFate::Missed);
    EXPECT_EQ(clipped.surface, 2);
    // A single lens passes its whole diameter.
    EXPECT_DOUBLE_EQ(usable_aperture_radius(plano_convex(sphere(kR)), kLineD), 12.5);
}

TEST(Aberrations, HexapolarBeamSamplesThePupil) {
    int lost = -1;
    const auto rays = trace_collimated_beam(plano_convex(sphere(kR)), kLineD, 10.0, 16, &lost);
    EXPECT_EQ(lost, 0);
    EXPECT_EQ(rays.size(), 1u + 3u * 16u * 17u);
}

}  // namespace
}  // namespace lenslab
