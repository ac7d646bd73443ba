// Surfaces not of revolution given in closed form (biconic, toroidal, XY polynomial, Zernike
// sag): their sags against the defining formulas and the surfaces of revolution they reduce
// to, their gradients against finite differences, and hits that lie on the surface.

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/lens/biconic_surface.h"
#include "geometry/lens/conic_surface.h"
#include "geometry/lens/polynomial_sag_surface.h"
#include "geometry/lens/spherical_surface.h"
#include "geometry/lens/toroidal_surface.h"
#include "math/rng.h"

namespace lenslab {
namespace {

// The gradient against a central difference at points of the square of half-width a.
void expect_gradient_matches(const AnalyticSagSurface& s, double a) {
    Rng rng(3, 5);
    const double h = 1e-6;
    for (int i = 0; i < 200; ++i) {
        const double x = (2 * rng.uniform() - 1) * a, y = (2 * rng.uniform() - 1) * a;
        double dx, dy;
        s.sag_and_gradient(x, y, dx, dy);
        EXPECT_NEAR(dx, (s.sag_xy(x + h, y) - s.sag_xy(x - h, y)) / (2 * h), 1e-7) << x << "," << y;
        EXPECT_NEAR(dy, (s.sag_xy(x, y + h) - s.sag_xy(x, y - h)) / (2 * h), 1e-7) << x << "," << y;
    }
}

// Rays from above and below at random points of the aperture: each hit lies on the surface.
void expect_hits_lie_on_the_surface(const AnalyticSagSurface& s, double a) {
    Rng rng(11, 2);
    const SurfaceSpan span = measure_span(s, a);
    int hits = 0;
    for (int i = 0; i < 400; ++i) {
        const Vec3 target{(2 * rng.uniform() - 1) * a * 0.7, (2 * rng.uniform() - 1) * a * 0.7, 0};
        const Vec3 origin{target.x + (rng.uniform() - 0.5) * a, target.y, i % 2 ? 40.0 : -40.0};
        const Ray ray{origin, normalize(target - origin)};
        double t;
        if (!s.intersect(ray, span, 0, INFINITY, t)) continue;
        ++hits;
        const Vec3 p = ray.at(t);
        EXPECT_NEAR(p.z, s.sag_xy(p.x, p.y), 1e-9);
    }
    EXPECT_GT(hits, 380);
}

TEST(BiconicSurface, SagIsTheTwoConicSections) {
    const double rx = 40, ry = -25, kx = -0.5, ky = 1.2;
    const BiconicSurface s(rx, ry, kx, ky);
    const double cx = 1 / rx, cy = 1 / ry;
    for (double x : {0.0, 3.0, -7.5}) {
        for (double y : {0.0, 4.0, -6.0}) {
            const double expected =
                (cx * x * x + cy * y * y) /
                (1 + std::sqrt(1 - (1 + kx) * cx * cx * x * x - (1 + ky) * cy * cy * y * y));
            EXPECT_NEAR(s.sag_xy(x, y), expected, 1e-14);
        }
    }
    // Each section alone is its conic.
    EXPECT_NEAR(s.sag_xy(6, 0), ConicSurface(rx, kx).sag(6), 1e-14);
    EXPECT_NEAR(s.sag_xy(0, 6), ConicSurface(ry, ky).sag(6), 1e-14);
    // The edge is the nearer of the two sections' edges: |R| / sqrt(1 + k).
    EXPECT_NEAR(s.max_semi_diameter(), 25 / std::sqrt(2.2), 1e-12);
    expect_gradient_matches(s, 10);
    expect_hits_lie_on_the_surface(s, 10);
}

TEST(BiconicSurface, EqualSectionsMakeTheConicAndAZeroRadiusACylinder) {
    const BiconicSurface equal(30, 30, -1.5, -1.5);
    const ConicSurface conic(30, -1.5);
    for (double x : {0.0, 2.0, -5.0}) {
        for (double y : {1.0, -8.0}) {
            EXPECT_NEAR(equal.sag_xy(x, y), conic.sag(std::hypot(x, y)), 1e-14);
        }
    }
    const BiconicSurface cylinder(0, 20, 0, 0);
    EXPECT_EQ(cylinder.sag_xy(9, 0), 0.0);
    EXPECT_NEAR(cylinder.sag_xy(9, 5), 20 - std::sqrt(400.0 - 25), 1e-13);
    expect_gradient_matches(cylinder, 12);
    expect_hits_lie_on_the_surface(cylinder, 12);
}

TEST(ToroidalSurface, ARotationRadiusEqualToTheCurvesMakesTheSphere) {
    const ToroidalSurface toroid(-35, 0, {}, -35);
    const SphericalSurface sphere(-35);
    for (double x : {0.0, 4.0, -9.0}) {
        for (double y : {0.0, 3.0, -7.0}) {
            EXPECT_NEAR(toroid.sag_xy(x, y), sphere.sag(std::hypot(x, y)), 1e-13);
        }
    }
    Rng rng(1, 1);
    for (int i = 0; i < 100; ++i) {
        const Vec3 p{(2 * rng.uniform() - 1) * 9, (2 * rng.uniform() - 1) * 9, 0};
        const Vec3 q{p.x, p.y, toroid.sag_xy(p.x, p.y)};
        EXPECT_NEAR(length(toroid.normal(q) - sphere.normal(q)), 0.0, 1e-12);
    }
}

TEST(ToroidalSurface, TheYCurveTurnsAboutAnAxisParallelToY) {
    // Zemax's TOROIDAL: the y-z curve (conic and even terms) swept about an axis parallel to
    // y at the radius of rotation R: z = R - sqrt((R - z_y)^2 - x^2).
    const double ry = 50, k = -0.8, a4 = 2e-6, a6 = -3e-9, rot = 80;
    const ToroidalSurface s(ry, k, {a4, a6}, rot);
    const auto zy = [&](double y) {
        return ConicSurface(ry, k).sag(y) + a4 * std::pow(y, 4) + a6 * std::pow(y, 6);
    };
    for (double y : {0.0, 5.0, -9.0}) {
        EXPECT_NEAR(s.sag_xy(0, y), zy(y), 1e-14);
        for (double x : {3.0, -8.0}) {
            EXPECT_NEAR(s.sag_xy(x, y), rot - std::sqrt(std::pow(rot - zy(y), 2) - x * x), 1e-13);
        }
    }
    // The x section through the vertex is a circle of the rotation radius.
    EXPECT_NEAR(s.sag_xy(7, 0), SphericalSurface(rot).sag(7), 1e-13);
    expect_gradient_matches(s, 10);
    expect_hits_lie_on_the_surface(s, 10);
    // A negative rotation radius bends the other way; 0 sweeps the curve straight.
    const ToroidalSurface concave(ry, k, {a4}, -60);
    EXPECT_NEAR(concave.sag_xy(7, 0), SphericalSurface(-60).sag(7), 1e-13);
    expect_gradient_matches(concave, 10);
    const ToroidalSurface cylinder(ry, k, {a4}, 0);
    EXPECT_NEAR(cylinder.sag_xy(9, 4), zy(4) - a6 * std::pow(4.0, 6), 1e-14);
    EXPECT_FALSE(cylinder.is_rotationally_symmetric());
}

TEST(XyPolynomialSurface, TermsInZemaxsOrderOnAnAsphereBase) {
    // x, y, x^2, xy, y^2, x^3, x^2 y: the first seven terms.
    const XyPolynomial p = xy_polynomial_from_terms({1, 2, 3, 4, 5, 6, 7});
    EXPECT_EQ(p.at(1, 0), 1);
    EXPECT_EQ(p.at(0, 1), 2);
    EXPECT_EQ(p.at(2, 0), 3);
    EXPECT_EQ(p.at(1, 1), 4);
    EXPECT_EQ(p.at(0, 2), 5);
    EXPECT_EQ(p.at(3, 0), 6);
    EXPECT_EQ(p.at(2, 1), 7);
    EXPECT_EQ(p.at(1, 2), 0);
    const double rn = 12, r = 60, k = -0.7, a4 = 3e-7;
    const PolynomialSagSurface s(r, k, {a4}, rn, p, "XY polynomial");
    for (double x : {0.0, 4.0, -7.0}) {
        for (double y : {0.0, 2.5, -9.0}) {
            const double u = x / rn, v = y / rn, rr = std::hypot(x, y);
            const double expected = ConicSurface(r, k).sag(rr) + a4 * std::pow(rr, 4) + u + 2 * v +
                                    3 * u * u + 4 * u * v + 5 * v * v + 6 * u * u * u +
                                    7 * u * u * v;
            EXPECT_NEAR(s.sag_xy(x, y), expected, 1e-12);
        }
    }
    expect_gradient_matches(s, 10);
}

TEST(XyPolynomialSurface, EqualSquareTermsOnAFlatBaseAreAParaboloid) {
    // C (x^2 + y^2) / R_n^2 is the paraboloid of vertex radius R_n^2 / (2C).
    const double rn = 10, c = 0.4;
    const PolynomialSagSurface s(0, 0, {}, rn, xy_polynomial_from_terms({0, 0, c, 0, c}),
                                 "XY polynomial");
    const ConicSurface paraboloid(rn * rn / (2 * c), -1);
    for (double x : {0.0, 3.0, -6.0}) {
        for (double y : {1.0, -8.0}) {
            EXPECT_NEAR(s.sag_xy(x, y), paraboloid.sag(std::hypot(x, y)), 1e-13);
            const Vec3 p{x, y, s.sag_xy(x, y)};
            EXPECT_NEAR(length(s.normal(p) - paraboloid.normal(p)), 0.0, 1e-13);
        }
    }
    expect_hits_lie_on_the_surface(s, 10);
}

TEST(ZernikeSagSurface, NollTermsOnTheNormalisationDisc) {
    // Zemax's Zernike Standard Sag: Z4 = √3 (2ρ² − 1), Z7 = √8 (3ρ³ − 2ρ) sin θ, Z11 =
    // √5 (6ρ⁴ − 6ρ² + 1), ρ = r / R_n; the constant of Z4 and Z11 stands the face off its
    // vertex plane.
    const double rn = 8, z4 = 0.01, z7 = -0.002, z11 = 0.003, r = -40;
    std::vector<double> noll(11, 0.0);
    noll[3] = z4;
    noll[6] = z7;
    noll[10] = z11;
    const PolynomialSagSurface s(r, 0, {}, rn, zernike_sag_polynomial(noll), "Zernike sag");
    for (double x : {0.0, 2.0, -5.0}) {
        for (double y : {0.0, 3.0, -6.0}) {
            const double rho = std::hypot(x, y) / rn, sin_t = rho > 0 ? y / (rho * rn) : 0.0;
            const double expected =
                SphericalSurface(r).sag(rho * rn) + z4 * std::sqrt(3.0) * (2 * rho * rho - 1) +
                z7 * std::sqrt(8.0) * (3 * std::pow(rho, 3) - 2 * rho) * sin_t +
                z11 * std::sqrt(5.0) * (6 * std::pow(rho, 4) - 6 * rho * rho + 1);
            EXPECT_NEAR(s.sag_xy(x, y), expected, 1e-13);
        }
    }
    expect_gradient_matches(s, 8);
    expect_hits_lie_on_the_surface(s, 8);
}

}  // namespace
}  // namespace lenslab
