// The aimed photons' sampling: the density of a direction in a union of cones (and of a
// point in a union of discs) must be the one the sampler draws from, or every aimed photon's
// power is wrong. Checked against the union's measure found by uniform sampling, which
// needs no density at all.

#include <gtest/gtest.h>

#include <cmath>

#include "math/constants.h"
#include "math/rng.h"
#include "math/sampling.h"
#include "scene/photon_targets.h"

namespace lenslab {
namespace {

TEST(PhotonTargets, ConeDensityIntegratesToTheUnionsSolidAngle) {
    // Two overlapping spheres and a separate one, seen from the origin. E_q[1 / q] is the
    // solid angle of the union when q is the sampler's density; uniform directions measure it
    // independently (the fraction inside any cone times 4 pi).
    const PhotonTargets targets({{{0, 0, 5}, 1.5}, {{0.8, 0, 5}, 1.5}, {{0, -6, 0}, 1.0}});
    Rng rng(7, 1);
    double sum_inverse = 0;
    constexpr int kSamples = 400000;
    for (int i = 0; i < kSamples; ++i) {
        Vec3 dir;
        double pdf;
        ASSERT_TRUE(targets.sample_direction({0, 0, 0}, rng.uniform(), rng.uniform(), rng.uniform(),
                                             4 * kPi, dir, pdf));
        EXPECT_NEAR(length(dir), 1.0, 1e-12);
        sum_inverse += 1.0 / pdf;
    }
    int inside = 0;
    for (int i = 0; i < kSamples; ++i) {
        const Vec3 d = sample_uniform_sphere(rng.uniform(), rng.uniform());
        for (const BoundingSphere& s : targets.spheres()) {
            const Vec3 c = s.centre;
            const double cos_max = std::sqrt(1 - s.radius * s.radius / length_squared(c));
            if (dot(d, normalize(c)) >= cos_max) {
                ++inside;
                break;
            }
        }
    }
    const double by_density = sum_inverse / kSamples, by_counting = 4 * kPi * inside / kSamples;
    std::printf("union solid angle: %.5f sr by the sampler's density, %.5f sr by counting\n",
                by_density, by_counting);
    EXPECT_NEAR(by_density, by_counting, 0.01 * by_counting);
}

TEST(PhotonTargets, EveryDirectionTowardsATargetCanBeDrawn) {
    // The cone holds the whole sphere it bounds: a ray to any point of the sphere is inside.
    const BoundingSphere s{{1, 2, 9}, 2.0};
    const PhotonTargets targets({s});
    Vec3 dir;
    double pdf;
    ASSERT_TRUE(targets.sample_direction({0, 0, 0}, 0.3, 0.4, 0.5, 4 * kPi, dir, pdf));
    const double d2 = length_squared(s.centre);
    const double solid_angle = 2 * kPi * (1 - std::sqrt(1 - s.radius * s.radius / d2));
    EXPECT_NEAR(pdf, 1 / solid_angle, 1e-9 / solid_angle);
    // From inside the sphere, every direction.
    ASSERT_TRUE(targets.sample_direction(s.centre, 0.3, 0.4, 0.5, 4.1 * kPi, dir, pdf));
    EXPECT_NEAR(pdf, 1 / (4 * kPi), 1e-12);
    // Not worth aiming when the cones cover more than the light's own sampling.
    EXPECT_FALSE(targets.sample_direction(s.centre, 0.3, 0.4, 0.5, 4 * kPi, dir, pdf));
}

TEST(PhotonTargets, PlaneDensityIntegratesToTheUnionsArea) {
    // Discs of radius 1 and 2 whose centres are 2 apart, projected on the plane z = 0 along
    // +z; a third sphere lies behind the plane and is skipped.
    const PhotonTargets targets({{{0, 0, 3}, 1.0}, {{2, 0, 7}, 2.0}, {{0, 0, -9}, 1.0}});
    Rng rng(3, 2);
    double sum_inverse = 0;
    constexpr int kSamples = 400000;
    for (int i = 0; i < kSamples; ++i) {
        Vec3 p;
        double pdf;
        ASSERT_TRUE(targets.sample_plane_point({0, 0, 0}, {0, 0, 1}, rng.uniform(), rng.uniform(),
                                               rng.uniform(), 1e9, p, pdf));
        EXPECT_NEAR(p.z, 0.0, 1e-12);
        sum_inverse += 1.0 / pdf;
    }
    // Area of the union: two circles (r1 = 1, r2 = 2, d = 2) overlap in the lens of area
    // r1^2 acos((d^2 + r1^2 - r2^2) / (2 d r1)) + r2^2 acos((d^2 + r2^2 - r1^2) / (2 d r2))
    //   - sqrt((-d + r1 + r2)(d + r1 - r2)(d - r1 + r2)(d + r1 + r2)) / 2.
    const double r1 = 1, r2 = 2, d = 2;
    const double lens =
        r1 * r1 * std::acos((d * d + r1 * r1 - r2 * r2) / (2 * d * r1)) +
        r2 * r2 * std::acos((d * d + r2 * r2 - r1 * r1) / (2 * d * r2)) -
        0.5 * std::sqrt((-d + r1 + r2) * (d + r1 - r2) * (d - r1 + r2) * (d + r1 + r2));
    const double expected = kPi * (r1 * r1 + r2 * r2) - lens;
    EXPECT_NEAR(sum_inverse / kSamples, expected, 0.01 * expected);
}

}  // namespace
}  // namespace lenslab
