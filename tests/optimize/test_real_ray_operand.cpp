// The real-ray operands (real_ray_x, real_ray_y: Zemax's REAX and REAY) against a ray traced
// by hand through the thick biconvex lens of test_merit_operand.cpp (n = 1.5, R1 = 50,
// R2 = -50, t = 5, the stop on its front face, EPD 4): the marginal ray of the axial field
// enters parallel to the axis at height 2, refracts at each sphere by Snell's law in vector
// form, and is followed to the image plane 48 behind the last vertex.

#include <gtest/gtest.h>

#include <cmath>

#include "optimize/design_evaluation.h"
#include "optimize_test_design.h"

namespace lenslab {
namespace {

using test::design_of;
using test::sphere;

struct HandRay {
    double y, z, dy, dz;  // in the meridional plane
};

// Through the sphere of radius r whose vertex is at z = vertex, from index n1 to n2.
HandRay refract_at_sphere(const HandRay& in, double vertex, double r, double n1, double n2) {
    const double cz = vertex + r;  // the centre
    // The meeting point on the vertex's side, |p - c|² = r² for p = (y, z) + s (dy, dz): the
    // nearer root for a face bulging towards the light (r > 0), the farther for one hollow
    // towards it.
    const double oy = in.y, oz = in.z - cz;
    const double b = oy * in.dy + oz * in.dz, c = oy * oy + oz * oz - r * r;
    const double s = -b - std::copysign(std::sqrt(b * b - c), r);
    const double y = in.y + s * in.dy, z = in.z + s * in.dz;
    double ny = y / std::abs(r), nz = (z - cz) / std::abs(r);
    if (ny * in.dy + nz * in.dz > 0) ny = -ny, nz = -nz;  // against the ray
    const double eta = n1 / n2, cosi = -(ny * in.dy + nz * in.dz);
    const double k = std::sqrt(1 - eta * eta * (1 - cosi * cosi));
    return {y, z, eta * in.dy + (eta * cosi - k) * ny, eta * in.dz + (eta * cosi - k) * nz};
}

TEST(RealRayOperand, TheMarginalRayMeetsTheImagePlaneWhereAHandTraceDoes) {
    const std::vector<test::LensSpec> lens = {{"B", 0.0, 5.0, 20.0, sphere(50), sphere(-50)}};
    const nlohmann::json operands = {
        {{"type", "real_ray_y"}, {"field", 0}, {"py", 1}, {"target", 0}},
        {{"type", "real_ray_x"}, {"field", 0}, {"px", -1}, {"target", 0}},
        {{"type", "real_ray_y"}, {"field", 0}, {"target", 0}}};
    const LensDesign d = lens_design_from_json(
        design_of(lens, {{"operands", operands}, {"image_distance", 48}}), "");
    ASSERT_EQ(d.operands.size(), 3u);
    EXPECT_EQ(operand_label(d.operands[0]), "real_ray_y 0° (0, 1)");
    const std::optional<DesignEvaluation> e = DesignModel(d).evaluate({});
    ASSERT_TRUE(e);
    HandRay ray{2, -10, 0, 1};
    ray = refract_at_sphere(ray, 0, 50, 1, 1.5);
    ray = refract_at_sphere(ray, 5, -50, 1.5, 1);
    const double image_z = 5 + 48;
    const double y = ray.y + (image_z - ray.z) / ray.dz * ray.dy;
    EXPECT_NEAR(e->values[0], y, 1e-9);
    EXPECT_NEAR(e->values[1], -y, 1e-9);  // the same ray turned about the axis
    EXPECT_NEAR(e->values[2], 0, 1e-12);  // the chief ray of the axial field
    // Short of the paraxial focus (BFL 49.15), a little above the axis: 2 (49.15 - 48) / 49.15
    // = 0.047, less the spherical aberration's pull.
    EXPECT_GT(y, 0.03);
    EXPECT_LT(y, 0.047);
}

}  // namespace
}  // namespace lenslab
