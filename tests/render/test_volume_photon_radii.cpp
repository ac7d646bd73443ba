// sppm's volume photon discs: sharp where photons crowd, as wide as their spacing where they
// are sparse, never below the sharp disc.

#include <gtest/gtest.h>

#include <vector>

#include "render/volume_photon_radii.h"

namespace lenslab {
namespace {

TEST(VolumePhotonRadii, CrowdedPhotonsKeepTheSharpDiscAndALoneOneSpreads) {
    // 200 photons packed within 0.001 of the origin, one alone 50 radii away; the eye 10
    // away, so the sharp disc is min(radius, 0.001 x 10) = 0.01.
    const double radius = 0.1;
    std::vector<Vec3> points;
    for (int i = 0; i < 200; ++i) points.push_back({0.00001 * i, 0.0002, 0.0003});
    points.push_back({5, 5, 5});
    const VolumeRadiusRule rule{radius, 0.001, {0, 0, -10}, 16};
    const std::vector<double> r = volume_photon_radii(
        points.size(), [&](size_t i) { return points[i]; }, rule);
    ASSERT_EQ(r.size(), points.size());
    EXPECT_NEAR(r[0], 0.6 * radius / 4, 1e-12) << "the finest cell holds them all";
    EXPECT_GE(r[0], 0.001 * 10 - 1e-12);
    EXPECT_NEAR(r.back(), 2.4 * radius, 1e-12) << "alone: the coarsest cell's radius";
}

TEST(VolumePhotonRadii, NeverBelowTheSharpDisc) {
    // A crowd far from the eye: the sharp disc, capped at the radius, is the larger.
    const double radius = 0.05;
    std::vector<Vec3> points(64, Vec3{0, 0, 100});
    const VolumeRadiusRule rule{radius, 0.01, {0, 0, 0}, 16};
    for (double r : volume_photon_radii(
             points.size(), [&](size_t i) { return points[i]; }, rule))
        EXPECT_DOUBLE_EQ(r, radius);
}

TEST(VolumePhotonRadii, WithoutNeighboursEveryDiscIsTheSharpOne) {
    const std::vector<Vec3> points{{0, 0, 1}, {0, 0, 50}, {3, 4, 0}};
    const VolumeRadiusRule rule{0.2, 0.01, {0, 0, 0}, 0};
    const std::vector<double> r = volume_photon_radii(
        points.size(), [&](size_t i) { return points[i]; }, rule);
    EXPECT_DOUBLE_EQ(r[0], 0.01);
    EXPECT_DOUBLE_EQ(r[1], 0.2);  // capped at the radius
    EXPECT_DOUBLE_EQ(r[2], 0.05);
}

}  // namespace
}  // namespace lenslab
