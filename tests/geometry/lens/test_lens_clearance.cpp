// The air space between neighbouring lens-group elements: the smallest axial distance from
// one element's back face to the next one's front face, over their common aperture.

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/lens/flat_surface.h"
#include "geometry/lens/lens_clearance.h"
#include "geometry/lens/sag_formula_surface.h"
#include "geometry/lens/spherical_surface.h"

namespace lenslab {
namespace {

TEST(LensClearance, TwoSpheresCloseAtTheRim) {
    // Back bulging forwards (R = 20), front bulging back (R = -20): 0.01 apart on the axis,
    // 0.01 - 2 (20 - sqrt(375)) at r = 5.
    const SphericalSurface back(20), front(-20);
    const Clearance c = smallest_clearance(back, front, 0.01, 5);
    EXPECT_NEAR(c.gap, 0.01 - 2 * (20 - std::sqrt(375.0)), 1e-12);
    EXPECT_NEAR(std::hypot(c.at.x, c.at.y), 5, 1e-12);
}

TEST(LensClearance, ApartEverywhereIsPositive) {
    const SphericalSurface back(-20), front(20);
    const Clearance c = smallest_clearance(back, front, 0.5, 5);
    EXPECT_NEAR(c.gap, 0.5, 1e-12);  // smallest on the axis
}

TEST(LensClearance, RefinesADipBetweenSamples) {
    // A dip 0.002 wide (two of the 4096 samples across r <= 4) to depth 0.5 at r = 1.23456:
    // the sampled minimum is refined to the dip's bottom.
    const FlatSurface back;
    const SagFormulaSurface front("-0.5*exp(-((r - 1.23456)/0.001)^2)", 4);
    const Clearance c = smallest_clearance(back, front, 0.4, 4);
    EXPECT_NEAR(c.gap, -0.1, 1e-9);
    EXPECT_NEAR(std::hypot(c.at.x, c.at.y), 1.23456, 1e-6);
}

TEST(LensClearance, FaceThatIsNotOfRevolution) {
    // A tilted plane behind a flat face: the gap 0.5 - 0.1 x is smallest at (2, 0).
    const SagFormulaSurface back("0.1*x", 2);
    const FlatSurface front;
    const Clearance c = smallest_clearance(back, front, 0.5, 2);
    EXPECT_NEAR(c.gap, 0.3, 1e-12);
    EXPECT_NEAR(c.at.x, 2, 1e-12);
    EXPECT_NEAR(c.at.y, 0, 1e-12);
}

}  // namespace
}  // namespace lenslab
