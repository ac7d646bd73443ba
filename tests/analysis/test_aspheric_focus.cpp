// A plano-convex lens whose convex face is a hyperboloid of conic constant k = -n^2 brings a
// collimated beam entering its flat face to a perfect point focus at f = |R| / (n - 1) behind
// the convex vertex: the refracting hyperbola of eccentricity e = n images the point at
// infinity inside the glass without aberration (Hecht, Optics, 5th ed., section 5.2.1,
// "Aspherical Surfaces"; Smith, Modern Optical Engineering, 4th ed., section 18.3). A
// spherical face of the same vertex radius has the same paraxial focal length but
// undercorrected spherical aberration.
//
// Traced through the scene reader and the ray tree (refracted branch at both faces), for the
// hyperboloid written as a conic, as an asphere and as a typed sag formula.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "analysis/trace/ray_tree.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

constexpr double kLensN = 1.5, kLensR = -50.0, kThickness = 5.0, kDiameter = 25.0;
constexpr double kFocalLength = -kLensR / (kLensN - 1.0);    // 100
constexpr double kFocusZ = 0.5 * kThickness + kFocalLength;  // back vertex at +d/2

Scene plano_convex(const std::string& back) {
    return parse_scene(R"({
      "camera": {"position": [0, 0, -200], "look_at": [0, 0, 0]},
      "objects": [{"type": "lens", "center": [0, 0, 0], "axis": [0, 0, 1],
                   "thickness": )" +
                       std::to_string(kThickness) + R"(, "diameter": )" +
                       std::to_string(kDiameter) + R"(,
                   "front": {"shape": "flat"}, "back": )" +
                       back + R"(,
                   "material": {"transparency": 1, "ior": )" +
                       std::to_string(kLensN) + R"(}}]
    })");
}

struct OutRay {
    Vec3 p, d;
};

// Follows the refracted branch through both faces.
std::vector<OutRay> trace_beam(const Scene& scene) {
    std::vector<OutRay> out;
    const double aperture = 0.45 * kDiameter;  // the beam fills 90% of the lens
    for (int ring = 1; ring <= 12; ++ring) {
        const double rho = aperture * ring / 12.0;
        for (int k = 0; k < 6 * ring; ++k) {
            const double phi = 2.0 * M_PI * (k + 0.5 * (ring % 2)) / (6 * ring);
            const RayTree tree = trace_ray_tree(
                scene, {{rho * std::cos(phi), rho * std::sin(phi), -50}, {0, 0, 1}}, {});
            const RayTreeNode* node = &tree.root;
            for (int face = 0; face < 2 && node; ++face) {
                const RayTreeNode* next = nullptr;
                for (const RayTreeNode& c : node->children) {
                    if (c.event == Event::Refract) next = &c;
                }
                node = next;
            }
            EXPECT_TRUE(node && node->to) << "ray at " << rho << " did not pass the lens";
            if (node && node->to) out.push_back({*node->to, node->direction});
        }
    }
    return out;
}

// RMS distance from the axis where the rays cross the plane z = z_plane.
double rms_at(const std::vector<OutRay>& rays, double z_plane) {
    double sum = 0;
    for (const OutRay& r : rays) {
        const double s = (z_plane - r.p.z) / r.d.z;
        const double x = r.p.x + s * r.d.x, y = r.p.y + s * r.d.y;
        sum += x * x + y * y;
    }
    return std::sqrt(sum / rays.size());
}

// Smallest RMS over all planes (the circle of least confusion in the RMS sense): the
// transverse position is p + s v, so RMS^2 is a quadratic in the plane's position.
double best_rms(const std::vector<OutRay>& rays) {
    double pv = 0, vv = 0;
    for (const OutRay& r : rays) {
        const double s = (kFocusZ - r.p.z) / r.d.z;
        const double px = r.p.x + s * r.d.x, py = r.p.y + s * r.d.y;
        const double vx = r.d.x / r.d.z, vy = r.d.y / r.d.z;
        pv += px * vx + py * vy;
        vv += vx * vx + vy * vy;
    }
    return rms_at(rays, kFocusZ - pv / vv);
}

TEST(AsphericFocus, HyperbolicPlanoConvexFocusesToAPoint) {
    const std::string k = std::to_string(-kLensN * kLensN);
    const std::string forms[] = {
        R"({"shape": "conic", "radius": -50, "k": )" + k + "}",
        R"({"shape": "asphere", "radius": -50, "k": )" + k + R"(, "coefficients": [0]})",
        // The same hyperboloid typed as z(r) = c r^2 / (1 + sqrt(1 - (1 + k) c^2 r^2)).
        R"j({"shape": "sag", "formula": "-r^2 / (50 * (1 + sqrt(1 + 1.25 * r^2 / 2500)))"})j",
    };
    const double sphere_paraxial =
        rms_at(trace_beam(plano_convex(R"({"shape": "sphere", "radius": -50})")), kFocusZ);
    const double sphere_best =
        best_rms(trace_beam(plano_convex(R"({"shape": "sphere", "radius": -50})")));
    for (const std::string& back : forms) {
        SCOPED_TRACE(back);
        const auto rays = trace_beam(plano_convex(back));
        ASSERT_EQ(rays.size(), 468u);
        const double rms = rms_at(rays, kFocusZ);
        std::printf(
            "hyperboloid %s: RMS spot %.3g (%.3g f); sphere: %.3g at the paraxial focus, "
            "%.3g at best focus (%.3g times larger)\n",
            back.c_str(), rms, rms / kFocalLength, sphere_paraxial, sphere_best, sphere_best / rms);
        EXPECT_LT(rms, 1e-6 * kFocalLength);
        // Spherical aberration: even at its best focus the sphere's spot is more than 100
        // times the hyperboloid's, and 100 times the 1e-6 f bound itself.
        EXPECT_GT(sphere_best, 100.0 * rms);
        EXPECT_GT(sphere_best, 100.0 * 1e-6 * kFocalLength);
    }
    // Undercorrected: the sphere's best focus lies in front of its paraxial focus, where the
    // spot is smaller.
    EXPECT_LT(sphere_best, sphere_paraxial);
}

}  // namespace
}  // namespace lenslab
