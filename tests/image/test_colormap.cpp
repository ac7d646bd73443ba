// The false-colour map against matplotlib's inferno table (_cm_listed.py, entries 0, 128
// and 255: values published with matplotlib 1.5, CC0), and its lightness rising.

#include <gtest/gtest.h>

#include "image/colormap.h"

namespace lenslab {
namespace {

TEST(Colormap, InfernoMatchesTheTable) {
    const struct {
        double t, r, g, b;
    } table[] = {{0.0, 0.001462, 0.000466, 0.013866},
                 {128.0 / 255, 0.735683, 0.215906, 0.330245},
                 {1.0, 0.988362, 0.998364, 0.644924}};
    for (const auto& e : table) {
        const Rgb c = inferno(e.t);
        EXPECT_NEAR(c.r, e.r, 0.02) << e.t;
        EXPECT_NEAR(c.g, e.g, 0.02) << e.t;
        EXPECT_NEAR(c.b, e.b, 0.02) << e.t;
    }
}

TEST(Colormap, LuminanceRisesAndInputIsClamped) {
    // Rec. 709 luma of the sRGB-encoded colour, a proxy for lightness, never falls.
    double last = -1;
    for (int i = 0; i <= 100; ++i) {
        const Rgb c = inferno(i / 100.0);
        const double y = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
        EXPECT_GE(y, last - 1e-3) << i;
        last = y;
    }
    EXPECT_EQ(inferno(-5).r, inferno(0).r);
    EXPECT_EQ(inferno(7).g, inferno(1).g);
    EXPECT_EQ(inferno(std::nan("")).b, inferno(0).b);
}

}  // namespace
}  // namespace lenslab
