// The vertex Taylor coefficients every lens surface gives the optical bench
// (geometry/lens/lens_surface.h, VertexSag): curvature and the r^4 coefficient. Closed forms:
// a sphere's sag R - sqrt(R^2 - r^2) = r^2 / (2R) + r^4 / (8R^3) + ...; a conic's fourth-order
// coefficient (1 + k) c^3 / 8 (Smith, Modern Optical Engineering, eq. 18.1 expanded); an even
// asphere adds its A4. A typed formula's are read off numerically and must agree.

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/lens/asphere_surface.h"
#include "geometry/lens/conic_surface.h"
#include "geometry/lens/flat_surface.h"
#include "geometry/lens/sag_formula_surface.h"
#include "geometry/lens/spherical_surface.h"

namespace lenslab {
namespace {

TEST(VertexSag, ClosedForms) {
    EXPECT_EQ(FlatSurface().vertex_sag(10).curvature, 0.0);
    EXPECT_EQ(FlatSurface().vertex_sag(10).a4, 0.0);
    const VertexSag sphere = SphericalSurface(-25.0).vertex_sag(10);
    EXPECT_DOUBLE_EQ(sphere.curvature, -1.0 / 25.0);
    EXPECT_DOUBLE_EQ(sphere.a4, -1.0 / (8.0 * 25.0 * 25.0 * 25.0));
    const VertexSag paraboloid = ConicSurface(40.0, -1.0).vertex_sag(10);
    EXPECT_DOUBLE_EQ(paraboloid.curvature, 1.0 / 40.0);
    EXPECT_EQ(paraboloid.a4, 0.0);
    const VertexSag asphere = AsphereSurface(40.0, -1.0, {3e-6, 1e-9}).vertex_sag(10);
    EXPECT_DOUBLE_EQ(asphere.a4, 3e-6);
}

TEST(VertexSag, TypedFormulasAgreeWithTheirClosedForms) {
    // A sphere of radius 50 written as its sag (with the cancellation a user's formula has).
    const VertexSag sphere = SagFormulaSurface("50 - sqrt(2500 - r^2)", 12.5).vertex_sag(12.5);
    EXPECT_NEAR(sphere.curvature, 1.0 / 50.0, 1e-11 / 50.0);
    const double sphere_a4 = 1.0 / (8.0 * 50.0 * 50.0 * 50.0);
    EXPECT_NEAR(sphere.a4, sphere_a4, 1e-7 * sphere_a4);
    // Polynomials in r^2 are exact to rounding.
    const VertexSag quartic = SagFormulaSurface("r^2 / 80 + 1e-5 * r^4", 12.5).vertex_sag(12.5);
    EXPECT_NEAR(quartic.curvature, 1.0 / 40.0, 1e-14);
    EXPECT_NEAR(quartic.a4, 1e-5, 1e-16);
    // A strongly curved face used to near its edge: R = 12 over a semi-diameter of 11.9.
    const VertexSag steep =
        SagFormulaSurface("r^2/(12*(1 + sqrt(1 - r^2/144)))", 11.9).vertex_sag(11.9);
    EXPECT_NEAR(steep.curvature, 1.0 / 12.0, 1e-12);
    EXPECT_NEAR(steep.a4, 1.0 / (8.0 * 12.0 * 12.0 * 12.0), 1e-12);
}

}  // namespace
}  // namespace lenslab
