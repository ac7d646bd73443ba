// Gradient-index lenses on the optical bench against closed forms.
// A radial rod n = n0 (1 - A r^2 / 2) of length L with flat faces, in air, has (Gomez-Reino,
// Perez and Bao, "Gradient-Index Optics", 2002, section 2.3; g = sqrt(A)):
//   EFL = 1 / (n0 g sin(g L)),   BFL = cos(g L) / (n0 g sin(g L)),   pitch = 2 pi / g,
// so a quarter-pitch rod focuses a collimated beam on its back face. An axial gradient
// n = n0 + A z bends no paraxial ray inside; a ray's reduced angle n u is constant, so its
// height grows by n u * integral dz / n = n u L ln(n2 / n1) / (n2 - n1).
// The real rays cross the same gaps by integrating the ray equation (scene/grin_ray.h), a
// computation independent of these closed forms.

#include <gtest/gtest.h>

#include <cmath>

#include "../lens_scene_builder.h"
#include "analysis/figures/ray_diagram.h"
#include "analysis/report/lens_report.h"
#include "analysis/system/grin_gap.h"
#include "analysis/system/paraxial.h"
#include "analysis/system/real_ray.h"
#include "math/constants.h"
#include "util/scene_error.h"

namespace lenslab {
namespace {

using test::lens_scene;
using test::LensSpec;
using test::sphere;

constexpr double kN0 = 1.6, kA = 0.25;  // scenes/grin_rod.json's rod, in millimetres

std::string radial(double n0, double a) {
    return R"({"transparency": 1, "grin": {"profile": "radial", "n0": )" + std::to_string(n0) +
           R"(, "A": )" + std::to_string(a) + "}}";
}

OpticalSystem rod(double length, const std::string& material = radial(kN0, kA)) {
    LensSpec spec{.name = "rod", .thickness = length, .diameter = 2, .material = material};
    return build_optical_system(lens_scene({spec}));
}

// Where a real ray parallel to the axis at height h crosses the axis, from the last vertex.
double real_axis_crossing(const OpticalSystem& system, double h) {
    const RealRay ray = trace_real_ray(system, {{0, h, -1}, {0, 0, 1}}, kLineD);
    EXPECT_EQ(ray.fate, RayFate::Passed);
    const Vec3 p = ray.exit_point(), d = ray.direction;
    return p.z - p.y / d.y * d.z - system.last_vertex();
}

TEST(GrinGap, RadialRodFocalLengthsFollowThePitch) {
    const double g = std::sqrt(kA), pitch = 2 * kPi / g;
    for (double fraction : {0.1, 0.2, 0.25, 0.3}) {
        const double length = fraction * pitch;
        const OpticalSystem system = rod(length);
        const ParaxialResult p = paraxial_trace(system, kLineD);
        const double efl = 1 / (kN0 * g * std::sin(g * length));
        const double bfl = std::cos(g * length) * efl;
        EXPECT_NEAR(p.efl, efl, 1e-9 * efl) << fraction << " pitch";
        EXPECT_NEAR(p.bfl, bfl, 1e-9 * efl) << fraction << " pitch";
        // The ray equation's integration agrees with the closed form near the axis.
        EXPECT_NEAR(real_axis_crossing(system, 0.005), bfl, 2e-4 * efl) << fraction << " pitch";
    }
}

TEST(GrinGap, QuarterPitchRodFocusesOnItsBackFace) {
    const double quarter = 0.5 * kPi / std::sqrt(kA);
    const OpticalSystem system = rod(quarter);
    EXPECT_NEAR(paraxial_trace(system, kLineD).bfl, 0, 1e-12);
    // A thin beam converges on the back face's centre.
    for (double h : {0.01, 0.05}) {
        const RealRay ray = trace_real_ray(system, {{0, h, -1}, {0, 0, 1}}, kLineD);
        ASSERT_EQ(ray.fate, RayFate::Passed);
        EXPECT_NEAR(ray.exit_point().y, 0, 2e-3 * h) << h;
    }
}

TEST(GrinGap, UniformProfileIsPlainGlass) {
    // A = 0: the radial profile is a constant n0, and a biconvex lens of it has the
    // thick-lens focal lengths of ordinary glass of index n0.
    const auto lens = [](const std::string& material) {
        LensSpec spec{.name = "l",
                      .thickness = 5,
                      .diameter = 20,
                      .front = sphere(50),
                      .back = sphere(-50),
                      .material = material};
        return paraxial_trace(build_optical_system(lens_scene({spec})), kLineD);
    };
    const ParaxialResult grin = lens(radial(1.5, 0));
    const ParaxialResult glass = lens(R"({"transparency": 1, "ior": 1.5})");
    EXPECT_NEAR(grin.efl, glass.efl, 1e-12 * glass.efl);
    EXPECT_NEAR(grin.bfl, glass.bfl, 1e-12 * glass.efl);
    EXPECT_NEAR(glass.efl, 50.8475, 1e-4);  // Hecht eq. 6.2
}

TEST(GrinGap, AxialGradientMovesTheFocusByTheLogIntegral) {
    // Plano-convex, R = 20, thickness 4, n = 1.6 + 0.02 z about the lens's mid-plane (the
    // profile's "center"): n = 1.56 at the front vertex and 1.64 at the flat back.
    const double r = 20, t = 4, n0 = 1.6, a = 0.02;
    const double n1 = n0 - a * t / 2, n2 = n0 + a * t / 2;
    LensSpec spec{.name = "axial",
                  .thickness = t,
                  .diameter = 8,
                  .front = sphere(r),
                  .material = R"({"transparency": 1, "grin": {"profile": "axial", "n0": 1.6,
                                  "A": 0.02, "center": [0, 0, 2]}})"};
    const OpticalSystem system = build_optical_system(lens_scene({spec}));
    const double power = (n1 - 1) / r;
    const double reduced_thickness = t * std::log(n2 / n1) / (n2 - n1);
    const double bfl = (1 - reduced_thickness * power) / power;
    const ParaxialResult p = paraxial_trace(system, kLineD);
    EXPECT_NEAR(p.efl, 1 / power, 1e-9 / power);
    EXPECT_NEAR(p.bfl, bfl, 1e-9 / power);
    EXPECT_NEAR(real_axis_crossing(system, 0.01), bfl, 1e-4 * bfl);
}

TEST(GrinGap, SteepRayLeavesThroughTheRim) {
    // A ray entering near the edge of a half-pitch rod at 37 degrees meets the cylinder wall
    // before the back face: the bench clips it there, as a lens edge.
    const OpticalSystem system = rod(kPi / std::sqrt(kA));
    const RealRay ray = trace_real_ray(system, {{0, 0.9, -0.1}, {0, 0.6, 0.8}}, kLineD);
    EXPECT_EQ(ray.fate, RayFate::Missed);
    EXPECT_EQ(ray.surface, 1);
}

TEST(GrinGap, RayDiagramDrawsTheRaysCurving) {
    // In a quarter-pitch rod a ray entering parallel at height y0 follows y0 cos(g z): the
    // diagram's rays carry the integrator's points inside, on that curve.
    const double g = std::sqrt(kA), quarter = 0.5 * kPi / g;
    const OpticalSystem system = rod(quarter);
    const RayDiagram diagram = make_ray_diagram(system, analyze_lens_system(system, {}), {});
    int curved = 0;
    for (const DiagramPath& path : diagram.paths) {
        std::vector<DiagramPoint> inside;
        for (const DiagramPoint& q : path.points) {
            if (q.z > 1e-9 && q.z < quarter - 1e-9) inside.push_back(q);
        }
        if (inside.size() < 3) continue;
        ++curved;
        // The ray's height before the rod; higher rays leave the paraxial curve (the profile's
        // spherical aberration, 0.14 at the rim).
        const double y0 = path.points.front().y;
        if (std::abs(y0) > 0.3) continue;
        for (const DiagramPoint& q : inside) {
            EXPECT_NEAR(q.y, y0 * std::cos(g * q.z), 0.02 * std::abs(y0) + 1e-9) << q.z;
        }
    }
    EXPECT_GE(curved, 12);  // the off-axis rays of the three colours' fans
}

TEST(GrinGap, ReportGivesThePitchAndNoSeidelSums) {
    const double g = std::sqrt(kA), quarter = 0.5 * kPi / g;
    const OpticalSystem system = rod(quarter);
    const nlohmann::ordered_json j = report_json(system, analyze_lens_system(system, {}));
    const auto& grin = j["lenses"][0]["grin"];
    EXPECT_EQ(grin["profile"], "radial");
    EXPECT_NEAR(grin["pitch"].get<double>(), 2 * kPi / g, 1e-12);
    EXPECT_NEAR(grin["pitches"].get<double>(), 0.25, 1e-12);
    EXPECT_TRUE(j["seidel"].is_null());
}

TEST(GrinGap, ProfilesWithoutTheAxisSymmetryAreRefused) {
    const std::string luneburg =
        R"({"transparency": 1, "grin": {"profile": "luneburg", "radius": 5}})";
    LensSpec spec{.name = "ball", .thickness = 2, .diameter = 4, .material = luneburg};
    try {
        build_optical_system(lens_scene({spec}));
        FAIL() << "a Luneburg profile is not a coaxial system";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("objects[0].material"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace lenslab
