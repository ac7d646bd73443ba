// Lens solids: hand-computed hits, the six classic forms, and a property test that every ray
// entering a lens finds its way out.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "geometry/lens/flat_surface.h"
#include "geometry/lens/lens_solid.h"
#include "geometry/lens/spherical_surface.h"
#include "math/frame.h"
#include "math/rng.h"
#include "math/sampling.h"

namespace lenslab {
namespace {

std::shared_ptr<const LensSurface> sphere(double r) {
    return std::make_shared<SphericalSurface>(r);
}
std::shared_ptr<const LensSurface> flat() { return std::make_shared<FlatSurface>(); }

LensPrescription make(double thickness, double diameter, std::shared_ptr<const LensSurface> front,
                      std::shared_ptr<const LensSurface> back, Vec3 centre = {},
                      Vec3 axis = {0, 0, 1}) {
    return {centre, normalize(axis), thickness, diameter, std::move(front), std::move(back)};
}

struct NamedForm {
    const char* name;
    LensPrescription p;
};

// The six classic forms, diameter 20, in the optics sign convention.
std::vector<NamedForm> six_forms() {
    return {
        {"biconvex", make(5, 20, sphere(50), sphere(-50))},
        {"biconcave", make(2, 20, sphere(-50), sphere(50))},
        {"plano-convex", make(4, 20, sphere(50), flat())},
        {"plano-concave", make(2, 20, flat(), sphere(50))},
        {"positive meniscus", make(4, 20, sphere(30), sphere(60))},
        {"negative meniscus", make(2, 20, sphere(60), sphere(30))},
    };
}

TEST(LensSolid, AxialRayHitsTheFrontVertex) {
    const LensSolid lens(make(5, 20, sphere(50), sphere(-50)));
    SurfaceHit h;
    ASSERT_TRUE(lens.intersect({{0, 0, -100}, {0, 0, 1}}, 0, INFINITY, h));
    EXPECT_NEAR(h.t, 97.5, 1e-12);
    EXPECT_NEAR(h.normal.z, -1.0, 1e-15);
    // From inside, the same ray leaves through the back vertex at z = +2.5.
    ASSERT_TRUE(lens.intersect({{0, 0, 0}, {0, 0, 1}}, 1e-9, INFINITY, h));
    EXPECT_NEAR(h.t, 2.5, 1e-12);
    EXPECT_NEAR(h.normal.z, 1.0, 1e-15);
}

TEST(LensSolid, OffAxisHitOnTheFrontFaceHandComputed) {
    // Front sphere R = 50 with its vertex at z = -2.5: centre at z = 47.5. At height y = 5
    // the sag is 50 - sqrt(2500 - 25) and the outward normal is (p - centre) / 50.
    const LensSolid lens(make(5, 20, sphere(50), sphere(-50)));
    SurfaceHit h;
    ASSERT_TRUE(lens.intersect({{0, 5, -100}, {0, 0, 1}}, 0, INFINITY, h));
    const double sag = 50.0 - std::sqrt(2475.0);
    EXPECT_NEAR(h.point.z, -2.5 + sag, 1e-12);
    EXPECT_NEAR(h.normal.y, 5.0 / 50.0, 1e-12);
    EXPECT_NEAR(h.normal.z, (-2.5 + sag - 47.5) / 50.0, 1e-12);
}

TEST(LensSolid, RimHitHasARadialNormal) {
    const LensSolid lens(make(5, 20, sphere(50), sphere(-50)));
    // Edge thickness 5 - 2 (50 - sqrt(2400)) = 2.9796; the rim spans z in +-1.4898.
    EXPECT_NEAR(lens.edge_thickness(), 5.0 - 2.0 * (50.0 - std::sqrt(2400.0)), 1e-12);
    SurfaceHit h;
    ASSERT_TRUE(lens.intersect({{-30, 0, 1.0}, {1, 0, 0}}, 0, INFINITY, h));
    EXPECT_NEAR(h.t, 20.0, 1e-12);
    EXPECT_NEAR(h.normal.x, -1.0, 1e-15);
    // Just above the rim's z-range the ray passes the rim and meets the back face inside
    // the diameter, where its sag is 2.5 - 1.6 = 0.9: r = sqrt(50^2 - 49.1^2).
    ASSERT_TRUE(lens.intersect({{-30, 0, 1.6}, {1, 0, 0}}, 0, INFINITY, h));
    EXPECT_NEAR(h.point.x, -std::sqrt(2500.0 - 49.1 * 49.1), 1e-10);
    EXPECT_GT(h.normal.z, 0.0);
}

TEST(LensSolid, ReportFormIsAKnifeEdgedSymmetricBiconvex) {
    // Two spheres of radius 1 meeting in a circle of radius 0.6: each cap has sag
    // 1 - sqrt(1 - 0.36) = 0.2, so the centre thickness is 0.4 and the edge thickness 0.
    const LensSolid lens(LensSolid::symmetric_biconvex({0, 0, 0}, {0, 0, 1}, 1.0, 0.6));
    EXPECT_NEAR(lens.prescription().thickness, 0.4, 1e-15);
    EXPECT_NEAR(lens.edge_thickness(), 0.0, 1e-15);
    SurfaceHit h;
    ASSERT_TRUE(lens.intersect({{0, 0, -3}, {0, 0, 1}}, 0, INFINITY, h));
    EXPECT_NEAR(h.point.z, -0.2, 1e-14);
}

TEST(LensSolid, RotatedLensMatchesTheAxisAlignedOne) {
    const Vec3 axis = normalize(Vec3{1, 2, 3});
    const Vec3 centre{4, -1, 2};
    const LensSolid lens(make(5, 20, sphere(50), sphere(-50), centre, axis));
    SurfaceHit h;
    ASSERT_TRUE(lens.intersect({centre - axis * 100.0, axis}, 0, INFINITY, h));
    EXPECT_NEAR(h.t, 97.5, 1e-10);
    EXPECT_NEAR(dot(h.normal, axis), -1.0, 1e-12);
}

TEST(LensSolid, PrescriptionChecksRefuseImpossibleLenses) {
    EXPECT_FALSE(LensSolid::check_prescription(make(5, 20, sphere(50), sphere(-50))));
    // Biconvex R = +-10 at diameter 10 needs centre thickness >= 2 * 10 * (1 - cos 30deg)...
    auto crossing = LensSolid::check_prescription(make(0.5, 10, sphere(10), sphere(-10)));
    ASSERT_TRUE(crossing);
    EXPECT_EQ(crossing->field, "thickness");
    EXPECT_NE(crossing->reason.find("cross"), std::string::npos);
    auto too_wide = LensSolid::check_prescription(make(5, 120, sphere(50), sphere(-50)));
    ASSERT_TRUE(too_wide);
    EXPECT_EQ(too_wide->field, "front");
    EXPECT_TRUE(LensSolid::check_prescription(make(0, 20, sphere(50), flat())));
    EXPECT_TRUE(LensSolid::check_prescription(make(5, -1, sphere(50), flat())));
}

TEST(LensSolid, SixFormsAreClosedAndHaveTheRightShape) {
    for (const auto& [name, p] : six_forms()) {
        SCOPED_TRACE(name);
        ASSERT_FALSE(LensSolid::check_prescription(p));
        const LensSolid lens(p);
        EXPECT_GE(lens.edge_thickness(), 0.0);
        EXPECT_TRUE(lens.contains({0, 0, 0}));
    }
    // Converging forms are thicker at the centre than at the edge, diverging ones thinner.
    const auto forms = six_forms();
    auto edge_minus_centre = [&](int i) {
        return LensSolid(forms[i].p).edge_thickness() - forms[i].p.thickness;
    };
    EXPECT_LT(edge_minus_centre(0), 0);  // biconvex
    EXPECT_GT(edge_minus_centre(1), 0);  // biconcave
    EXPECT_LT(edge_minus_centre(2), 0);  // plano-convex
    EXPECT_GT(edge_minus_centre(3), 0);  // plano-concave
    EXPECT_LT(edge_minus_centre(4), 0);  // positive meniscus
    EXPECT_GT(edge_minus_centre(5), 0);  // negative meniscus
}

// 10^5 random rays over the six forms in random poses: a ray that enters always finds an
// exit (in any inward direction, as refraction may send it), normals are unit length and
// point out of the solid.
TEST(LensSolid, EveryRayThatEntersExits) {
    Rng rng(2024, 1);
    const auto forms = six_forms();
    int entered = 0;
    for (int i = 0; i < 100000; ++i) {
        LensPrescription p = forms[i % forms.size()].p;
        p.axis = sample_uniform_sphere(rng.uniform(), rng.uniform());
        p.centre = Vec3{rng.uniform(), rng.uniform(), rng.uniform()} * 10.0;
        const LensSolid lens(p);
        // Aim from a point on a sphere of radius 60 around the lens at a point of its box.
        const Aabb box = lens.bounds();
        const Vec3 target =
            box.lo + Vec3{box.extent().x * rng.uniform(), box.extent().y * rng.uniform(),
                          box.extent().z * rng.uniform()};
        const Vec3 origin = p.centre + sample_uniform_sphere(rng.uniform(), rng.uniform()) * 60.0;
        const Vec3 d = normalize(target - origin);
        SurfaceHit in;
        if (!lens.intersect({origin, d}, 0, INFINITY, in)) continue;
        ++entered;
        ASSERT_NEAR(length(in.normal), 1.0, 1e-12);
        ASSERT_LT(dot(d, in.normal), 0.0) << "first hit from outside must be an entry";
        // Outward: a step along the normal leaves the solid, a step against it enters.
        const double step = 1e-6;
        ASSERT_FALSE(lens.contains(in.point + in.normal * step));
        ASSERT_TRUE(lens.contains(in.point - in.normal * step));

        // Any inward direction from the entry point must reach an exit.
        Vec3 inward = sample_cosine_hemisphere(rng.uniform(), rng.uniform());
        inward = Frame::from_axis(-in.normal).to_world(inward);
        SurfaceHit out;
        ASSERT_TRUE(lens.intersect({in.point, inward}, surface_epsilon(in.point), INFINITY, out))
            << forms[i % forms.size()].name << " ray " << i;
        ASSERT_NEAR(length(out.normal), 1.0, 1e-12);
        ASSERT_GT(dot(inward, out.normal), 0.0) << "the next hit from inside must be an exit";
    }
    EXPECT_GT(entered, 50000);  // the property was exercised, not skipped
}

}  // namespace
}  // namespace lenslab
