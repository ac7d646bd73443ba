// Absorption from the catalogues' extinction coefficient k: the internal transmittance it
// gives against the maker's data sheet, and its behaviour at and beyond the table's ends.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "optics/absorption.h"
#include "optics/glass_library.h"

namespace lenslab {
namespace {

TEST(Absorption, InternalTransmittanceMatchesTheSchottDataSheet) {
    // SCHOTT data sheet N-BK7 (517642.251), internal transmittance tau_i through 10 mm:
    // 0.933 at 1970 nm, 0.793 at 2325 nm, 0.665 at 2500 nm. The catalogue's k must give them
    // back through tau = exp(-4 pi k d / lambda) within 0.5%.
    const Glass* bk7 = lookup_glass("SCHOTT:N-BK7").glass;
    ASSERT_NE(bk7, nullptr);
    ASSERT_FALSE(bk7->k_um.empty());
    EXPECT_NEAR(internal_transmittance(bk7->k_um, 1970, 10), 0.933, 0.005 * 0.933);
    EXPECT_NEAR(internal_transmittance(bk7->k_um, 2325, 10), 0.793, 0.005 * 0.793);
    EXPECT_NEAR(internal_transmittance(bk7->k_um, 2500, 10), 0.665, 0.005 * 0.665);
    // Clear in the visible: above 0.99 through 10 mm from 400 to 700 nm.
    for (double nm = 400; nm <= 700; nm += 50) {
        EXPECT_GT(internal_transmittance(bk7->k_um, nm, 10), 0.99) << nm;
    }
}

TEST(Absorption, CoefficientFromK) {
    // alpha = 4 pi k / lambda: k = 1e-6 at 500 nm is 4 pi / 0.5 per metre = 0.02513 per mm.
    const std::vector<std::pair<double, double>> k{{0.4, 2e-6}, {0.5, 1e-6}, {0.6, 1e-6}};
    EXPECT_NEAR(absorption_per_mm(k, 500), 4 * std::numbers::pi * 1e-6 / 500e-6, 1e-15);
    // Linear in k between the points: k = 1.5e-6 at 450 nm.
    EXPECT_NEAR(absorption_per_mm(k, 450), 4 * std::numbers::pi * 1.5e-6 / 450e-6, 1e-12);
    // Beyond the table k holds the end values.
    EXPECT_NEAR(absorption_per_mm(k, 360), 4 * std::numbers::pi * 2e-6 / 360e-6, 1e-12);
    EXPECT_NEAR(absorption_per_mm(k, 800), 4 * std::numbers::pi * 1e-6 / 800e-6, 1e-12);
    EXPECT_EQ(absorption_per_mm({}, 500), 0.0);
    // Beer-Lambert over 2 units of alpha 0.5: e^-1; scene units of 10 mm scale alpha.
    EXPECT_NEAR(beer_lambert(0.5, 2.0), std::exp(-1.0), 1e-15);
    const Absorption in_cm(k, 10.0);
    EXPECT_NEAR(in_cm.transmittance(500, 1.0), internal_transmittance(k, 500, 10.0), 1e-15);
}

}  // namespace
}  // namespace lenslab
