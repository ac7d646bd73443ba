// Conic, asphere and typed sag surfaces on their own: sags against closed forms, hits that
// lie on the surface, normals against the gradient, and no wrong hit from a formula that
// jumps.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "geometry/lens/asphere_surface.h"
#include "geometry/lens/conic_surface.h"
#include "geometry/lens/sag_formula_surface.h"
#include "geometry/lens/spherical_surface.h"
#include "math/rng.h"
#include "math/sampling.h"

namespace lenslab {
namespace {

// Rays from points around the surface aimed at random points of the disc's neighbourhood.
std::vector<Ray> rays_towards(double a, double height, int n, uint64_t seed) {
    Rng rng(seed, 7);
    std::vector<Ray> rays;
    for (int i = 0; i < n; ++i) {
        const Vec3 target{(2 * rng.uniform() - 1) * a, (2 * rng.uniform() - 1) * a,
                          (2 * rng.uniform() - 1) * height};
        const Vec3 origin = target + sample_uniform_sphere(rng.uniform(), rng.uniform()) * 4.0 * a;
        rays.push_back({origin, normalize(target - origin)});
    }
    return rays;
}

TEST(ConicSurface, SagsOfTheNamedConics) {
    // Paraboloid (k = -1): r^2 / 2R exactly; sphere (k = 0): R - sqrt(R^2 - r^2);
    // hyperboloid k < -1: (1 - sqrt(1 - (1 + k) c^2 r^2)) / ((1 + k) c) (the other root form).
    const double R = 20, r = 7;
    EXPECT_NEAR(ConicSurface(R, -1).sag(r), r * r / (2 * R), 1e-15);
    EXPECT_NEAR(ConicSurface(R, 0).sag(r), R - std::sqrt(R * R - r * r), 1e-14);
    const double k = -2.25, c = 1 / R;
    EXPECT_NEAR(ConicSurface(R, k).sag(r),
                (1 - std::sqrt(1 - (1 + k) * c * c * r * r)) / ((1 + k) * c), 1e-14);
    // Only a prolate/oblate ellipsoid or sphere has an edge: 1 / (|c| sqrt(1 + k)).
    EXPECT_NEAR(ConicSurface(R, 1).max_semi_diameter(), R / std::sqrt(2.0), 1e-12);
    EXPECT_TRUE(std::isinf(ConicSurface(R, -1).max_semi_diameter()));
    EXPECT_TRUE(std::isinf(ConicSurface(R, -3).max_semi_diameter()));
}

TEST(ConicSurface, WithZeroConicConstantItIsTheSphere) {
    const ConicSurface conic(-30, 0);
    const SphericalSurface sphere(-30);
    const SurfaceSpan span{12};
    for (const Ray& ray : rays_towards(12, 3, 2000, 1)) {
        double tc, ts;
        const bool hc = conic.intersect(ray, span, 0, INFINITY, tc);
        ASSERT_EQ(hc, sphere.intersect(ray, span, 0, INFINITY, ts));
        if (!hc) continue;
        EXPECT_NEAR(tc, ts, 1e-10);
        const Vec3 nc = conic.normal(ray.at(tc)), ns = sphere.normal(ray.at(ts));
        EXPECT_NEAR(length(nc - ns), 0.0, 1e-12);
    }
}

TEST(ConicSurface, HyperboloidHitsLieOnTheVertexSheet) {
    const ConicSurface s(25, -2.3);
    const SurfaceSpan span{15};
    int hits = 0;
    for (const Ray& ray : rays_towards(15, 6, 4000, 2)) {
        double t;
        if (!s.intersect(ray, span, 0, INFINITY, t)) continue;
        ++hits;
        const Vec3 p = ray.at(t);
        EXPECT_NEAR(p.z, s.sag(std::hypot(p.x, p.y)), 1e-11);
        EXPECT_GT(s.normal(p).z, 0.0);
    }
    EXPECT_GT(hits, 1000);
}

TEST(AsphereSurface, SagAndSlopeOfTheEvenPolynomial) {
    const double R = 40, k = -0.6, A4 = 2e-5, A6 = -3e-8, A8 = 1e-11;
    const AsphereSurface s(R, k, {A4, A6, A8});
    const ConicSurface base(R, k);
    for (double r : {0.0, 1.0, 5.5, 12.0}) {
        const double poly = A4 * std::pow(r, 4) + A6 * std::pow(r, 6) + A8 * std::pow(r, 8);
        EXPECT_NEAR(s.sag(r), base.sag(r) + poly, 1e-14);
        const double h = 1e-5;
        EXPECT_NEAR(s.slope(r), (s.sag(r + h) - s.sag(r - h)) / (2 * h), 1e-9);
    }
    // With no polynomial it is its base conic.
    const AsphereSurface plain(R, k, {0.0});
    EXPECT_EQ(plain.sag(9.0), base.sag(9.0));
}

// The numerical intersection of an asphere and a sag formula agrees with the closed form of
// the same conic, and finds the nearest crossing.
TEST(NumericalSags, AgreeWithTheClosedFormConic) {
    const double R = -18, k = -1.7, a = 10;
    const ConicSurface exact(R, k);
    const AsphereSurface asphere(R, k, {0.0});
    const SagFormulaSurface formula("r^2 / (" + std::to_string(R) + " * (1 + sqrt(1 - (1 + " +
                                        std::to_string(k) + ") * r^2 / " + std::to_string(R * R) +
                                        ")))",
                                    a);
    EXPECT_NEAR(formula.sag(7.0), exact.sag(7.0), 1e-12);
    const SurfaceSpan span = measure_span(exact, a);
    int hits = 0;
    for (const Ray& ray : rays_towards(a, 4, 5000, 3)) {
        double te, ta, tf;
        const bool he = exact.intersect(ray, span, 0, INFINITY, te);
        const bool ha = asphere.intersect(ray, span, 0, INFINITY, ta);
        const bool hf = formula.intersect(ray, span, 0, INFINITY, tf);
        ASSERT_EQ(he, ha);
        ASSERT_EQ(he, hf);
        if (!he) continue;
        ++hits;
        EXPECT_NEAR(ta, te, 1e-9 * std::max(1.0, te));
        EXPECT_NEAR(tf, te, 1e-9 * std::max(1.0, te));
        const Vec3 n = exact.normal(ray.at(te));
        EXPECT_NEAR(length(asphere.normal(ray.at(ta)) - n), 0.0, 1e-9);
        EXPECT_NEAR(length(formula.normal(ray.at(tf)) - n), 0.0, 1e-8);
    }
    EXPECT_GT(hits, 1000);
}

TEST(SagFormulaSurface, RevolutionOrNot) {
    const SagFormulaSurface round("r^2/100");
    EXPECT_TRUE(round.is_rotationally_symmetric());
    EXPECT_DOUBLE_EQ(round.sag_xy(3, 4), 0.25);
    const SagFormulaSurface cylinder("x^2/100");
    EXPECT_FALSE(cylinder.is_rotationally_symmetric());
    EXPECT_DOUBLE_EQ(cylinder.sag_xy(3, 4), 0.09);
    EXPECT_DOUBLE_EQ(cylinder.sag(5), 0.25);               // along +x
    const SagFormulaSurface mixed("r^2/100 + 0.001*x*y");  // r is allowed with x and y
    EXPECT_FALSE(mixed.is_rotationally_symmetric());
    EXPECT_DOUBLE_EQ(mixed.sag_xy(3, 4), 0.25 + 0.012);
    // The normal of the cylinder has no y component.
    const Vec3 n = cylinder.normal({5, 2, 0.25});
    EXPECT_NEAR(n.y, 0.0, 1e-12);
    EXPECT_NEAR(n.x / n.z, -0.1, 1e-9);  // -dz/dx = -2x/100
}

TEST(SagFormulaSurface, RefusesWhatCannotBeASurface) {
    EXPECT_EQ(*SagFormulaSurface::check("r^2/*2"),
              "cannot parse at position 5: Unexpected operator \"*\"");
    EXPECT_EQ(*SagFormulaSurface::check("r^2 + q"), "unknown variable 'q' (use r, or x and y)");
    EXPECT_FALSE(SagFormulaSurface::check("x*y/50"));
    try {
        SagFormulaSurface s("1 + r^2");
        FAIL() << "a sag of 1 at the vertex was accepted";
    } catch (const FormulaError& e) {
        EXPECT_EQ(e.message(),
                  "must be 0 on the axis (z is measured from the vertex), got 1 at r = 0");
    }
}

// A sag that jumps (a step at r = 5) has no root at the jump: rays across it find the step's
// flat parts or nothing, never a point off the surface.
TEST(SagFormulaSurface, AJumpIsNeverAHit) {
    const SagFormulaSurface step("(r > 5) * 2");
    const SurfaceSpan span = measure_span(step, 10);
    int hits = 0;
    for (const Ray& ray : rays_towards(10, 3, 20000, 4)) {
        double t;
        if (!step.intersect(ray, span, 0, INFINITY, t)) continue;
        ++hits;
        const Vec3 p = ray.at(t);
        ASSERT_NEAR(p.z, step.sag_xy(p.x, p.y), 1e-7) << "a hit off the surface";
    }
    EXPECT_GT(hits, 1000);
}

}  // namespace
}  // namespace lenslab
