// Detectors against physics: the Fresnel share of a beam through a lens arriving at its
// focus, the inverse-square and cosine law of a point light, the power a disc intercepts
// from a point light and from a glowing sphere; and what a detector must not do: count a
// photon twice, count the wrong face, depend on the thread count.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>

#include "analysis/detectors/detector.h"
#include "math/constants.h"
#include "scene/scene_json.h"
#include "util/scene_error.h"

namespace lenslab {
namespace {

DetectionResult measure(const Scene& scene, int64_t photons, int threads = 0) {
    return measure_detectors(scene, {.photons_per_light = photons, .threads = threads});
}

const DetectorMeasurement& only(const DetectionResult& r) {
    EXPECT_EQ(r.detectors.size(), 1u);
    return r.detectors.at(0);
}

// Unpolarised Fresnel transmittance from index n1 into n2 at incidence angle `theta`
// (Hecht, Optics, 5th ed., eqs. 4.42-4.43: r_s, r_p; R = (r_s^2 + r_p^2) / 2, T = 1 - R).
double fresnel_t_detector(double theta, double n1, double n2) {
    const double sin_t = n1 / n2 * std::sin(theta);
    const double ci = std::cos(theta), ct = std::sqrt(1 - sin_t * sin_t);
    const double rs = (n1 * ci - n2 * ct) / (n1 * ci + n2 * ct);
    const double rp = (n2 * ci - n1 * ct) / (n2 * ci + n1 * ct);
    return 1 - 0.5 * (rs * rs + rp * rp);
}

TEST(Detector, LensFocusReceivesTheBeamTimesTheFresnelTransmission) {
    // A plano-convex N-BK7 lens (R = 25.8 mm, flat back, centre thickness 5.3 mm: f = 49.9
    // mm), curved side to a 1 W beam of radius a = 5 mm at 587.6 nm, where N-BK7 has
    // n_d = 1.5168 (SCHOTT data sheet). A ray at height h meets the sphere at
    // theta1 = asin(h / R), enters at asin(sin(theta1) / n) and so crosses the glass at
    // theta2 = theta1 - asin(sin(theta1) / n) to the axis, which is its incidence angle on
    // the flat back. The detector, at the paraxial focus, receives
    //   P = (1 W) * (1 / (pi a^2)) * integral_0^a T(theta1; 1 -> n) T(theta2; n -> 1) 2 pi h dh
    // from light crossing each face once; light reflected twice inside adds at most R^2 of
    // that (0.2%), within the 1% asked.
    const double n = 1.5168, radius = 25.8, a = 5;
    double expected = 0;
    constexpr int kSteps = 2000;
    for (int i = 0; i < kSteps; ++i) {
        const double h = (i + 0.5) * a / kSteps;
        const double theta1 = std::asin(h / radius);
        const double theta2 = theta1 - std::asin(std::sin(theta1) / n);
        expected += fresnel_t_detector(theta1, 1, n) * fresnel_t_detector(theta2, n, 1) * 2 * h *
                    (a / kSteps) / (a * a);
    }
    // The paraxial back focal distance f - t / n = R / (n - 1) - t / n behind the flat back.
    const double bfd = radius / (n - 1) - 5.3 / n, focus = 2.65 + bfd;
    std::ostringstream text;
    text << std::setprecision(17) << R"({"camera": {"position": [0, 0, -100], "look_at": [0, 0, 0]},
        "objects": [{"type": "lens", "center": [0, 0, 0], "axis": [0, 0, 1], "thickness": 5.3, "diameter": 25.4,
                     "front": {"shape": "sphere", "radius": 25.8}, "back": {"shape": "flat"},
                     "material": {"transparency": 1, "glass": "N-BK7"}},
                    {"name": "focus", "type": "disc", "center": [0, 0, )"
         << focus << R"(], "normal": [0, 0, -1],
                     "radius": 1, "material": {"color": 0.5}, "detector": {"resolution": 64, "unit": "mm"}}],
        "lights": [{"type": "beam", "origin": [0, 0, -20], "direction": [0, 0, 1], "radius": 5, "power": 1,
                    "spectrum": {"line": 587.56}}]})";
    const DetectorMeasurement m = only(measure(parse_scene(text.str()), 200000));
    std::printf(
        "focus at z = %.3f: P = %.5f W, expected %.5f W (%+.3f%%); centroid (%.2e, %.2e), rms "
        "radius %.4f mm\n",
        focus, m.total_power, expected, 100 * (m.total_power / expected - 1), m.centroid_u,
        m.centroid_v, m.rms_radius);
    EXPECT_NEAR(m.total_power, expected, 0.01 * expected);
    EXPECT_GT(expected, 0.90);  // the integral itself: about (1 - 0.042)^2 near the axis
    EXPECT_LT(expected, 0.92);
    // On the axis: the centroid within 2% of the spot's RMS radius, a spot far smaller
    // than the beam.
    EXPECT_GT(m.rms_radius, 0);
    EXPECT_LT(m.rms_radius, 0.05 * a);
    EXPECT_LT(std::hypot(m.centroid_u, m.centroid_v), 0.02 * m.rms_radius);
    EXPECT_NEAR(m.centroid.z, focus, 1e-9);
}

// Average over a cell [u0, u1] x [v0, v1] of the irradiance of a point light of power P at
// height d above the plane: E = I cos(theta) / r^2 with I = P / (4 pi) and
// cos(theta) = d / r (inverse square and Lambert's cosine law; Hecht, section 3.3.1).
double cell_irradiance(double power, double d, double u0, double u1, double v0, double v1) {
    constexpr int k = 40;
    double sum = 0;
    for (int i = 0; i < k; ++i) {
        for (int j = 0; j < k; ++j) {
            const double u = u0 + (i + 0.5) * (u1 - u0) / k, v = v0 + (j + 0.5) * (v1 - v0) / k;
            const double r = std::sqrt(d * d + u * u + v * v);
            sum += power / (4 * kPi) * d / (r * r * r);
        }
    }
    return sum / (k * k);
}

TEST(Detector, PointLightIrradianceFollowsInverseSquareAndCosine) {
    // A 4 x 4 rectangle facing +y, 1 below a 100 W point light.
    const Scene scene = parse_scene(R"({"camera": {"position": [0, 5, 5], "look_at": [0, 0, 0]},
        "objects": [{"type": "rectangle", "center": [0, 0, 0], "normal": [0, 1, 0], "size": [4, 4],
                     "material": {"color": 0.5}, "detector": {"resolution": [16, 16]}}],
        "lights": [{"type": "point", "position": [0, 1, 0], "power": 100}]})");
    const DetectorMeasurement m = only(measure(scene, 2000000));
    const DetectorGrid& g = m.grid;
    for (const auto& [u, v] :
         {std::pair{0.1, 0.1}, std::pair{0.6, -0.1}, std::pair{-0.4, 0.6}, std::pair{0.9, 0.9}}) {
        const int c = g.cell_at(u, v);
        const double hw = 0.5 * g.cell_width(), hh = 0.5 * g.cell_height();
        const double expected = cell_irradiance(100, 1, g.cell_u(c) - hw, g.cell_u(c) + hw,
                                                g.cell_v(c) - hh, g.cell_v(c) + hh);
        std::printf("cell at (%.3f, %.3f): E = %.4f W/unit^2, expected %.4f (%+.2f%%)\n",
                    g.cell_u(c), g.cell_v(c), m.irradiance(c), expected,
                    100 * (m.irradiance(c) / expected - 1));
        EXPECT_NEAR(m.irradiance(c), expected, 0.04 * expected);
    }
}

TEST(Detector, DiscInterceptsTheSolidAngleItSubtendsOfAPointLight) {
    // A disc of radius a on the axis at distance d from an isotropic source of power P
    // receives P Omega / (4 pi) = P / 2 (1 - d / sqrt(d^2 + a^2)) (the solid angle of a
    // cone of half-angle atan(a / d)).
    const double p = 100, d = 1, a = 1;
    const Scene scene = parse_scene(R"({"camera": {"position": [0, 5, 5], "look_at": [0, 0, 0]},
        "objects": [{"type": "disc", "center": [0, 0, 0], "normal": [0, 1, 0], "radius": 1,
                     "material": {"color": 0.5}, "detector": true}],
        "lights": [{"type": "point", "position": [0, 1, 0], "power": 100}]})");
    const DetectorMeasurement m = only(measure(scene, 400000));
    const double expected = p / 2 * (1 - d / std::sqrt(d * d + a * a));
    std::printf("P = %.4f W, expected %.4f W (%+.3f%%)\n", m.total_power, expected,
                100 * (m.total_power / expected - 1));
    EXPECT_NEAR(m.total_power, expected, 0.01 * expected);
    EXPECT_LT(std::hypot(m.centroid_u, m.centroid_v), 0.01);
}

TEST(Detector, DiscInterceptsTheFluxOfAGlowingSphere) {
    // A Lambertian sphere of radius s and radiance L lights a point at distance r from its
    // centre, whose normal makes angle theta with the direction to it, with
    // E = pi L (s / r)^2 cos(theta) while the sphere is wholly above the point's horizon.
    // Over a disc of radius a on the axis at distance d:
    //   P = 2 pi^2 L s^2 (1 - d / sqrt(d^2 + a^2)).
    const double l = 10, s = 0.2, d = 1, a = 1;
    const Scene scene = parse_scene(R"({"camera": {"position": [0, 5, 5], "look_at": [0, 0, 0]},
        "objects": [{"type": "disc", "center": [0, 0, 0], "normal": [0, 1, 0], "radius": 1,
                     "material": {"color": 0}, "detector": true},
                    {"type": "sphere", "center": [0, 1, 0], "radius": 0.2,
                     "material": {"color": 0, "emission": {"color": 1, "intensity": 10}}}]})");
    const DetectorMeasurement m = only(measure(scene, 400000));
    const double expected = 2 * kPi * kPi * l * s * s * (1 - d / std::sqrt(d * d + a * a));
    std::printf("P = %.4f W, expected %.4f W (%+.3f%%)\n", m.total_power, expected,
                100 * (m.total_power / expected - 1));
    EXPECT_NEAR(m.total_power, expected, 0.015 * expected);
}

// A 1 W beam of radius 0.5 along +z through `objects`.
Scene beam_scene(const std::string& objects, const std::string& spectrum = R"("color": 1)") {
    return parse_scene(
        R"({"camera": {"position": [0, 5, 5], "look_at": [0, 0, 0]}, "objects": [)" + objects +
        R"(], "lights": [{"type": "beam", "origin": [0, 0, -5], "direction": [0, 0, 1], "radius": 0.5,
                                         "power": 1, )" +
        spectrum + "}]}");
}

TEST(Detector, VirtualSensorCountsEachPhotonOnceAndPassesItOn) {
    // A transparent detector with ior 1 lets every photon through unchanged: it and the
    // opaque detector behind it both receive the whole beam, exactly once, and the beam's
    // footprint behind it is the uniform disc of radius 0.5 (RMS radius 0.5 / sqrt 2).
    const Scene scene = beam_scene(R"(
        {"name": "virtual", "type": "disc", "center": [0, 0, 0], "normal": [0, 0, -1], "radius": 1,
         "material": {"color": 1, "transparency": 1, "ior": 1}, "detector": true},
        {"name": "screen", "type": "rectangle", "center": [0, 0, 2], "normal": [0, 0, -1], "size": [2, 2],
         "material": {"color": 0.5}, "detector": {"resolution": 32}})");
    const DetectionResult r = measure(scene, 50000);
    ASSERT_EQ(r.detectors.size(), 2u);
    for (const DetectorMeasurement& m : r.detectors) {
        SCOPED_TRACE(m.name);
        EXPECT_NEAR(m.total_power, 1.0, 1e-9);
        EXPECT_EQ(m.arrivals, 50000);
        EXPECT_NEAR(m.rms_radius, 0.5 / std::sqrt(2.0), 0.01 * 0.5 / std::sqrt(2.0));
        EXPECT_LT(std::hypot(m.centroid_u, m.centroid_v), 0.005);
    }
}

TEST(Detector, CountsTheFaceItIsAskedFor) {
    // The beam meets these discs from behind (their normals point along the beam).
    for (const auto& [side, expected] :
         {std::pair{"front", 0.0}, std::pair{"back", 1.0}, std::pair{"both", 1.0}}) {
        const Scene scene =
            beam_scene(std::string(R"({"type": "disc", "center": [0, 0, 0], "normal": [0, 0, 1],
            "radius": 1, "material": {"color": 0.5}, "detector": {"side": ")") +
                       side + R"("}})");
        EXPECT_NEAR(only(measure(scene, 1000)).total_power, expected, 1e-9) << side;
    }
}

TEST(Detector, SameResultWhateverTheThreadCount) {
    const Scene scene = beam_scene(R"(
        {"type": "sphere", "center": [0, 0, 0], "radius": 0.6, "material": {"transparency": 1, "glass": "N-SF11"}},
        {"type": "disc", "center": [0, 0, 3], "normal": [0, 0, -1], "radius": 2,
         "material": {"color": 0.5}, "detector": {"resolution": 48}})");
    const DetectorMeasurement one = only(measure(scene, 100000, 1));
    const DetectorMeasurement two = only(measure(scene, 100000, 2));
    EXPECT_EQ(one.power, two.power);
    EXPECT_EQ(one.band_power, two.band_power);
    EXPECT_EQ(one.total_power, two.total_power);
    EXPECT_EQ(one.centroid_u, two.centroid_u);
}

// Planck's law B(l, T) = 2 h c^2 / l^5 / (exp(h c / (l k T)) - 1) (CODATA 2018 constants),
// its share in [lo, hi] nm of the range 360-830 nm.
double planck_share(double kelvin, double lo, double hi) {
    auto planck = [kelvin](double nm) {
        const double h = 6.62607015e-34, c = 299792458.0, k = 1.380649e-23, l = nm * 1e-9;
        return 2 * h * c * c / std::pow(l, 5) / std::expm1(h * c / (l * k * kelvin));
    };
    auto integral = [&](double a, double b) {
        double s = 0;
        for (int i = 0; i < 10000; ++i)
            s += planck(a + (i + 0.5) * (b - a) / 10000) * (b - a) / 10000;
        return s;
    };
    return integral(lo, hi) / integral(360, 830);
}

TEST(Detector, BandsHoldTheSpectrumTheyCover) {
    // A 532 nm laser line falls wholly in the 490-585 nm band.
    const std::string screen =
        R"({"type": "disc", "center": [0, 0, 3], "normal": [0, 0, -1], "radius": 2,
        "material": {"color": 0.5}, "detector": {"bands": [360, 450, 550, 650, 830]}})";
    const DetectorMeasurement laser =
        only(measure(beam_scene(screen, R"("spectrum": {"line": 532})"), 2000));
    ASSERT_EQ(laser.bands(), 4);
    EXPECT_NEAR(laser.band_total[1] + laser.band_total[2], 1.0, 1e-9);
    EXPECT_NEAR(laser.band_total[2], 0.0, 1e-9);
    // Black-body light arriving with its whole spectrum: each band holds Planck's share.
    const DetectorMeasurement bb =
        only(measure(beam_scene(screen, R"("spectrum": {"blackbody": 4000})"), 2000));
    const double edges[] = {360, 450, 550, 650, 830};
    for (int b = 0; b < 4; ++b) {
        EXPECT_NEAR(bb.band_total[static_cast<size_t>(b)],
                    planck_share(4000, edges[b], edges[b + 1]), 1e-4)
            << b;
    }
}

TEST(Detector, SingleWavelengthPhotonsKeepTheSpectrum) {
    // Inside a closed box of black detectors, a black-body beam through a dispersive glass
    // ball: photons refracted by the ball each carry one sampled wavelength, and every
    // photon ends on a wall. The walls together receive the whole beam, each band
    // Planck's share of it (up to sampling noise). The ball is N-SF11's Sellmeier model
    // given as `ior`: the catalogue glass would absorb some of the beam (Beer-Lambert,
    // tests/analysis/test_glass_absorption.cpp), and here only the bookkeeping is tested.
    std::string walls;
    const char* faces[][3] = {
        {"[0, 0, -4]", "[0, 0, 1]", "[8, 8]"}, {"[0, 0, 4]", "[0, 0, -1]", "[8, 8]"},
        {"[-4, 0, 0]", "[1, 0, 0]", "[8, 8]"}, {"[4, 0, 0]", "[-1, 0, 0]", "[8, 8]"},
        {"[0, -4, 0]", "[0, 1, 0]", "[8, 8]"}, {"[0, 4, 0]", "[0, -1, 0]", "[8, 8]"}};
    for (const auto& f : faces) {
        walls += std::string(R"(, {"type": "rectangle", "center": )") + f[0] + R"(, "normal": )" +
                 f[1] + R"(, "size": )" + f[2] + R"(, "material": {"color": 0},
                   "detector": {"resolution": 8, "bands": [360, 450, 550, 650, 830]}})";
    }
    // Emitted photons each keep exactly their share of the beam: only those still inside the
    // ball at the depth limit are lost. Aimed ones (at a ball narrower than the beam, so that
    // aiming is denser than the beam) split at the glass and keep it on average.
    for (const bool aim : {false, true}) {
        SCOPED_TRACE(aim ? "aimed" : "emitted");
        const Scene scene = parse_scene(R"({"camera": {"position": [0, 0, 3], "look_at": [0, 0, 0]},
            "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": )" +
                                        std::string(aim ? "0.3" : "0.8") + R"(,
                         "material": {"transparency": 1, "ior": {"model": "sellmeier", "B": [1.73759695, 0.313747346, 1.89878101], "C": [0.013188707, 0.0623068142, 155.23629]}}})" +
                                        walls + R"(],
            "lights": [{"type": "beam", "origin": [0, 0, -3], "direction": [0, 0, 1], "radius": 0.5, "power": 1,
                        "spectrum": {"blackbody": 4000}}]})");
        RenderControl control;
        DetectionSettings settings;
        settings.photons_per_light = 200000;
        settings.aim = aim;
        const DetectionResult r = measure_detectors(scene, settings, control);
        ASSERT_EQ(r.detectors.size(), 6u);
        EXPECT_EQ(r.photons_aimed, aim ? 200000 : 0);
        double total = 0, band[4] = {};
        for (const DetectorMeasurement& m : r.detectors) {
            total += m.total_power;
            double sum = 0;
            for (int b = 0; b < 4; ++b) {
                band[b] += m.band_total[static_cast<size_t>(b)];
                sum += m.band_total[static_cast<size_t>(b)];
            }
            // The same photons summed in two groupings: rounding over 200000 additions.
            EXPECT_NEAR(sum, m.total_power, 1e-12 + 1e-10 * m.total_power);
        }
        EXPECT_NEAR(total, 1.0, aim ? 3e-3 : 1e-6);
        const double edges[] = {360, 450, 550, 650, 830};
        for (int b = 0; b < 4; ++b) {
            const double share = planck_share(4000, edges[b], edges[b + 1]);
            std::printf("%g-%g nm: %.4f W, Planck %.4f W\n", edges[b], edges[b + 1], band[b],
                        share);
            EXPECT_NEAR(band[b], share, 0.02 * share) << "band " << b;
        }
    }
}

TEST(Detector, NoDetectorsNoWork) {
    const DetectionResult r =
        measure(beam_scene(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1,
        "material": {"color": 0.5}})"),
                1000);
    EXPECT_TRUE(r.detectors.empty());
}

}  // namespace
}  // namespace lenslab
