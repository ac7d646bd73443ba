// Photons aimed at the glass must not change what is measured, only how soon it is
// measured well (render/photon_emission.h). A point light above a thin biconvex lens with
// a knife edge lights a detector disc below it, partly through the lens and partly past its
// edge; the power the disc receives has a closed form, and aimed and uniform emission must
// both give it, at several seeds.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "analysis/detectors/detector.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

// Unpolarised Fresnel transmittance for incidence cosine `cos_i` from n1 into n2 (Hecht,
// Optics, 5th ed., eqs. 4.42-4.43).
double fresnel_t(double cos_i, double n1, double n2) {
    const double sin_t = n1 / n2 * std::sqrt(1 - cos_i * cos_i);
    const double ct = std::sqrt(1 - sin_t * sin_t);
    const double rs = (n1 * cos_i - n2 * ct) / (n1 * cos_i + n2 * ct);
    const double rp = (n2 * cos_i - n1 * ct) / (n2 * cos_i + n1 * ct);
    return 1 - 0.5 * (rs * rs + rp * rp);
}

// Distance along unit `u` from `o` to the sphere (c, r): the nearer or the farther root.
double to_sphere(const Vec3& o, const Vec3& u, const Vec3& c, double r, bool far) {
    const Vec3 oc = o - c;
    const double b = dot(oc, u), q = length_squared(oc) - r * r;
    const double root = std::sqrt(b * b - q);
    return far ? -b + root : -b - root;
}

// The scene: lens of two R = 100 spheres meeting at aperture radius a = 10 (centre thickness
// 2 (R - sqrt(R^2 - a^2)) = 1.0), axis +z, centre at the origin, index 1.5; 1 W point light at
// z = -40; black detector disc of radius 15 at z = 1 facing the light.
constexpr double kR = 100, kA = 10, kN = 1.5, kLightZ = -40, kDiscZ = 1, kDiscRadius = 15;

std::string scene_text() {
    std::ostringstream s;
    s << R"({"camera": {"position": [0, 0, -100], "look_at": [0, 0, 0]},
        "objects": [{"type": "lens", "center": [0, 0, 0], "axis": [0, 0, 1], "curvature_radius": )"
      << kR << R"(, "aperture_radius": )" << kA << R"(, "material": {"transparency": 1, "ior": )"
      << kN << R"(}},
                    {"name": "disc", "type": "disc", "center": [0, 0, )"
      << kDiscZ << R"(], "normal": [0, 0, -1],
                     "radius": )"
      << kDiscRadius << R"(, "material": {"color": 0}, "detector": true}],
        "lights": [{"type": "point", "position": [0, 0, )"
      << kLightZ << R"(], "power": 1}]})";
    return s.str();
}

// P / (4 pi) times: the solid angle between the lens's edge and the disc's edge (light past
// the lens; the knife edge at z = 0 is the lens's silhouette, its front face bulging inside
// that cone), plus the integral over the lens's cone of T(front) T(back) for each ray,
// traced exactly through the two spheres. Light reflected twice inside (about R^2 = 0.2% of
// what crosses) is left out.
double expected_power() {
    const double d = std::sqrt(kR * kR - kA * kA);
    const Vec3 light{0, 0, kLightZ}, front_centre{0, 0, d}, back_centre{0, 0, -d};
    const double theta_lens = std::atan(kA / -kLightZ);
    const double theta_disc = std::atan(kDiscRadius / (kDiscZ - kLightZ));
    double through = 0;
    constexpr int kSteps = 20000;
    for (int i = 0; i < kSteps; ++i) {
        const double theta = (i + 0.5) * theta_lens / kSteps;
        const Vec3 u{std::sin(theta), 0, std::cos(theta)};
        const Vec3 p1 = light + u * to_sphere(light, u, front_centre, kR, false);
        const Vec3 n1 = (p1 - front_centre) / kR;  // outward, towards the light
        const double cos1 = -dot(u, n1), eta = 1 / kN;
        const double cos_t = std::sqrt(1 - eta * eta * (1 - cos1 * cos1));
        const Vec3 inside = u * eta + n1 * (eta * cos1 - cos_t);
        const Vec3 p2 = p1 + inside * to_sphere(p1, inside, back_centre, kR, true);
        const double cos2 = dot(inside, (p2 - back_centre) / kR);
        through += fresnel_t(cos1, 1, kN) * fresnel_t(cos2, kN, 1) * std::sin(theta) *
                   (theta_lens / kSteps);
    }
    const double past = std::cos(theta_lens) - std::cos(theta_disc);  // solid angle / (2 pi)
    return (past + through) / 2.0;                                    // P / (4 pi) * 2 pi (...)
}

TEST(AimedPhotons, DetectorBehindALensGetsTheSamePowerAsWithUniformPhotons) {
    const Scene scene = parse_scene(scene_text());
    ASSERT_TRUE(scene.is_photon_target(0));
    ASSERT_FALSE(scene.is_photon_target(1));
    const double expected = expected_power();
    for (uint64_t seed : {1, 2, 3}) {
        RenderControl control;
        DetectionSettings uniform;
        uniform.photons_per_light = 2000000;
        uniform.aim = false;
        uniform.seed = seed;
        const DetectionResult u = measure_detectors(scene, uniform, control);
        DetectionSettings aimed = uniform;
        aimed.aim = true;
        aimed.caustic_photons_per_light = 200000;
        const DetectionResult a = measure_detectors(scene, aimed, control);
        ASSERT_EQ(a.photons_aimed, 200000);
        const double pu = u.detectors.at(0).total_power, pa = a.detectors.at(0).total_power;
        std::printf(
            "seed %llu: uniform %.5f W (%lld arrivals), aimed %.5f W (%lld arrivals), closed form "
            "%.5f W\n",
            static_cast<unsigned long long>(seed), pu,
            static_cast<long long>(u.detectors[0].arrivals), pa,
            static_cast<long long>(a.detectors[0].arrivals), expected);
        // Uniform: about 60 000 arrivals, 0.4% noise; aimed: the lens part at 0.1%.
        EXPECT_NEAR(pu, expected, 0.015 * expected);
        EXPECT_NEAR(pa, expected, 0.01 * expected);
        EXPECT_NEAR(pa, pu, 0.015 * expected);
    }
}

TEST(AimedPhotons, TheLensPartAloneIsTheFresnelTransmissionOfWhatTheLensIntercepts) {
    // The aimed stream alone (no emitted photons): only light through the lens reaches the
    // disc, and all of it must.
    const Scene scene = parse_scene(scene_text());
    RenderControl control;
    DetectionSettings s;
    s.photons_per_light = 0;
    s.caustic_photons_per_light = 400000;
    const DetectionResult r = measure_detectors(scene, s, control);
    const double past = (std::cos(std::atan(kA / -kLightZ)) -
                         std::cos(std::atan(kDiscRadius / (kDiscZ - kLightZ)))) /
                        2;
    const double expected = expected_power() - past;
    const double intercepted = (1 - std::cos(std::atan(kA / -kLightZ))) / 2;  // P Omega / (4 pi)
    std::printf(
        "through the lens: %.6f W of the %.6f W it intercepts (T = %.4f); expected %.6f W\n",
        r.detectors.at(0).total_power, intercepted, r.detectors.at(0).total_power / intercepted,
        expected);
    EXPECT_NEAR(r.detectors.at(0).total_power, expected, 0.005 * expected);
    // Normal incidence on both faces would give (1 - 0.04)^2 = 0.9216.
    EXPECT_NEAR(expected / intercepted, 0.9216, 0.005);
}

}  // namespace
}  // namespace lenslab
