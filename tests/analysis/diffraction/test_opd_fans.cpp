// OPD fans (analysis/diffraction/opd_fans.h):
// - a perfect F/10 mirror with its image plane moved off the focus by half a wave of defocus
//   (W020 = δz/(8N²)) has the fans W = W020 py² and W020 px² (to the 1e-3 of the defocus'
//   higher orders at F/10), 0 at the chief ray;
// - off the axis its tangential fan is odd about the chief ray (coma, W131 py³, with the
//   tilt the chief-ray reference leaves) and the sagittal fan even;
// - a field whose chief ray does not pass gives NaN fans, not an error.

#include <gtest/gtest.h>

#include <cmath>

#include "analysis/diffraction/opd_fans.h"
#include "paraboloid_bench.h"

namespace lenslab {
namespace {

constexpr double kFanFocal = 1000.0, kFanDiameter = 100.0;  // F/10

TEST(OpdFans, DefocusIsAParabolaInBothFans) {
    const test::MirrorBench b = test::mirror_bench(kFanFocal, kFanDiameter, 0);
    const double w020 = 0.5, n = kFanFocal / kFanDiameter;
    RayFanOptions o;
    o.points = 11;
    o.wavelengths = {kLineD};
    o.image_z = -kFanFocal + w020 * kLineD * 1e-6 * 8 * n * n;
    const RayFans fans = opd_fans(b.system, b.first, o);
    ASSERT_EQ(fans.fields.size(), 1u);
    ASSERT_EQ(fans.pupil.size(), 11u);
    const RayFan& fan = fans.fields[0].fans[0];
    for (size_t k = 0; k < fans.pupil.size(); ++k) {
        const double p = fans.pupil[k];
        EXPECT_NEAR(std::abs(fan.tangential[k]), w020 * p * p, 1e-3 * w020) << p;
        EXPECT_NEAR(fan.sagittal[k], fan.tangential[k], 1e-9) << p;
    }
    EXPECT_NEAR(fan.tangential[5], 0.0, 1e-12);
    ASSERT_TRUE(fans.fields[0].reference);
    EXPECT_NEAR(fans.fields[0].reference->z, *o.image_z, 1e-9);
}

TEST(OpdFans, ComaMakesTheTangentialFanOddAndTheSagittalEven) {
    const double field = 0.5;
    const test::MirrorBench b = test::mirror_bench(kFanFocal, kFanDiameter, field);
    RayFanOptions o;
    o.fields = {field, 89};
    o.points = 9;
    o.wavelengths = {kLineD};
    const RayFans fans = opd_fans(b.system, b.first, o);
    const RayFan& fan = fans.fields[0].fans[0];
    const size_t last = fans.pupil.size() - 1;
    for (size_t k = 0; k <= last; ++k)
        EXPECT_NEAR(fan.sagittal[k], fan.sagittal[last - k], 1e-6) << k;
    // Coma's W131 py³ (0.46 waves, test_field_wavefront.cpp) makes the rim points differ by
    // about twice that; astigmatism and field curvature are even.
    EXPECT_GT(std::abs(fan.tangential[0] - fan.tangential[last]), 0.5);
    EXPECT_NEAR(fan.tangential[last / 2], 0.0, 1e-12);
    const RayFan& lost = fans.fields[1].fans[0];
    EXPECT_TRUE(std::isnan(lost.tangential[0]));
    EXPECT_TRUE(std::isnan(lost.sagittal[last]));
}

}  // namespace
}  // namespace lenslab
