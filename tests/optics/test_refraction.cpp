// Snell's law and the law of reflection in vector form (Hecht, Optics, section 4.4).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "math/rng.h"
#include "math/sampling.h"
#include "optics/refraction.h"

namespace lenslab {
namespace {

double sin_angle(const Vec3& a, const Vec3& n) { return length(cross(a, n)); }

TEST(Refraction, SnellsLawHoldsForRandomDirections) {
    Rng rng(7, 0);
    const Vec3 n{0, 0, 1};
    for (int i = 0; i < 10000; ++i) {
        Vec3 d = sample_uniform_sphere(rng.uniform(), rng.uniform());
        if (d.z > -1e-3) d.z = -std::abs(d.z) - 1e-3;  // arriving from above
        d = normalize(d);
        for (auto [n1, n2] : {std::pair{1.0, 1.5}, std::pair{1.5, 1.0}, std::pair{1.0, 2.4}}) {
            const auto t = refract(d, n, n1 / n2);
            const double lhs = n1 * sin_angle(d, n);
            if (lhs >= n2) {  // beyond the critical angle
                EXPECT_FALSE(t.has_value());
                continue;
            }
            ASSERT_TRUE(t.has_value());
            EXPECT_NEAR(length(*t), 1.0, 1e-12);
            EXPECT_NEAR(lhs, n2 * sin_angle(*t, n), 1e-12);  // n1 sin(a) = n2 sin(b)
            EXPECT_LT(t->z, 0.0);                            // continues through the surface
            EXPECT_NEAR(dot(cross(d, n), *t), 0.0, 1e-12);   // stays in the plane of incidence
        }
    }
}

TEST(Refraction, CriticalAngleOfGlassToAir) {
    const Vec3 n{0, 0, 1};
    const double theta_c = std::asin(1.0 / 1.5);  // 41.81 degrees
    auto dir = [](double a) { return Vec3{std::sin(a), 0, -std::cos(a)}; };
    EXPECT_TRUE(refract(dir(theta_c - 1e-6), n, 1.5).has_value());
    EXPECT_FALSE(refract(dir(theta_c + 1e-6), n, 1.5).has_value());
}

TEST(Refraction, ReflectionKeepsTheAngle) {
    const Vec3 d = normalize(Vec3{1, 2, -3});
    const Vec3 n{0, 0, 1};
    const Vec3 r = reflect(d, n);
    EXPECT_NEAR(r.x, d.x, 1e-15);
    EXPECT_NEAR(r.y, d.y, 1e-15);
    EXPECT_NEAR(r.z, -d.z, 1e-15);
    EXPECT_NEAR(length(reflect(d, -n) - r), 0.0, 1e-15);  // either normal orientation
}

TEST(Refraction, NormalIncidenceGoesStraightThrough) {
    const auto t = refract({0, 0, -1}, {0, 0, 1}, 1.0 / 1.5);
    ASSERT_TRUE(t.has_value());
    EXPECT_NEAR(t->z, -1.0, 1e-15);
}

}  // namespace
}  // namespace lenslab
