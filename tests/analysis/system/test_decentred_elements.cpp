// Decentred and tilted lens group elements on the bench: real rays against an independent
// trace written here (spheres placed by hand with Zemax's order-0 coordinate break:
// decentre, then tilt about x, then about the turned y), and the first-order figures about
// the central chief ray (parabasal) against closed forms.

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "analysis/report/lens_report.h"
#include "analysis/system/first_order.h"
#include "analysis/system/optical_system.h"
#include "analysis/system/parabasal.h"
#include "analysis/system/paraxial.h"
#include "analysis/system/real_ray.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

using nlohmann::json;

constexpr double kSingletIndex = 1.5;  // a constant index: the test is about geometry
constexpr double kSingletR1 = 50, kSingletR2 = -40, kSingletThickness = 5, kSingletDiameter = 25;

json decentred_singlet(const json& moves) {
    json element = {{"front", {{"shape", "sphere"}, {"radius", kSingletR1}}},
                    {"back", {{"shape", "sphere"}, {"radius", kSingletR2}}},
                    {"thickness", kSingletThickness},
                    {"material", {{"color", 1}, {"transparency", 1}, {"ior", kSingletIndex}}}};
    element.update(moves);
    return {{"camera", {{"position", {0, 0, -100}}, {"look_at", {0, 0, 0}}}},
            {"objects",
             {{{"type", "lens_group"},
               {"vertex", {0, 0, 0}},
               {"axis", {0, 0, 1}},
               {"diameter", kSingletDiameter},
               {"elements", {element}}}}}};
}

OpticalSystem decentred_system(const json& scene) {
    return build_optical_system(scene_from_json(scene));
}

// The independent trace: a ray through two spheres and Snell's law in vector form.
struct HandRay {
    Vec3 p, d;
};

Vec3 turned_by(const std::array<Vec3, 3>& columns, const Vec3& v) {
    return columns[0] * v.x + columns[1] * v.y + columns[2] * v.z;
}

// The sphere of radius r whose vertex is `vertex` (its centre at vertex + axis r): the ray
// meets it on the vertex's side, and refracts from index n1 to n2.
HandRay hand_sphere(const HandRay& ray, const Vec3& vertex, const Vec3& axis, double r, double n1,
                    double n2) {
    const Vec3 centre = vertex + axis * r;
    const Vec3 oc = ray.p - centre;
    const double b = dot(oc, ray.d), c = dot(oc, oc) - r * r;
    const double root = std::sqrt(b * b - c);
    Vec3 p = ray.p + ray.d * (-b - root);
    if (dot(p - centre, axis) * r > 0) p = ray.p + ray.d * (-b + root);
    Vec3 n = (p - centre) * (1.0 / std::abs(r));
    if (dot(n, ray.d) > 0) n = -n;
    const double eta = n1 / n2, cosi = -dot(n, ray.d);
    const double k = 1 - eta * eta * (1 - cosi * cosi);
    return {p, ray.d * eta + n * (eta * cosi - std::sqrt(k))};
}

TEST(DecentredElements, RealRaysMatchAnIndependentTrace) {
    const double dx = 0.4, dy = -0.3, tx = 3.0, ty = -2.0;  // degrees
    const OpticalSystem system = decentred_system(decentred_singlet(
        {{"decenter_x", dx}, {"decenter_y", dy}, {"tilt_x", tx}, {"tilt_y", ty}}));
    ASSERT_FALSE(system.coaxial());
    // Zemax order 0: the new axes are Rx(tx) Ry(ty) applied to the old.
    const double a = tx * M_PI / 180, b = ty * M_PI / 180;
    const std::array<Vec3, 3> rx{Vec3{1, 0, 0}, Vec3{0, std::cos(a), std::sin(a)},
                                 Vec3{0, -std::sin(a), std::cos(a)}};
    const std::array<Vec3, 3> ry{Vec3{std::cos(b), 0, -std::sin(b)}, Vec3{0, 1, 0},
                                 Vec3{std::sin(b), 0, std::cos(b)}};
    const Vec3 w = turned_by(rx, turned_by(ry, {0, 0, 1}));
    const Vec3 front{dx, dy, 0};
    const Vec3 back = front + w * kSingletThickness;
    for (const auto& [x, y] :
         std::array<std::pair<double, double>, 5>{{{0, 0}, {5, 0}, {0, -7}, {-6, 4}, {3.3, 8.1}}}) {
        const Ray start{{x, y, -10}, normalize(Vec3{0.01, -0.02, 1})};
        const HandRay in =
            hand_sphere({start.origin, start.direction}, front, w, kSingletR1, 1, kSingletIndex);
        const HandRay out = hand_sphere(in, back, w, kSingletR2, kSingletIndex, 1);
        const RealRay ray = trace_real_ray(system, start, kLineD);
        ASSERT_EQ(ray.fate, RayFate::Passed) << x << ", " << y;
        for (const auto& [bench, hand] :
             {std::pair{ray.points[1], in.p}, std::pair{ray.points[2], out.p},
              std::pair{ray.direction, out.d}}) {
            EXPECT_NEAR(bench.x, hand.x, 1e-9) << x << ", " << y;
            EXPECT_NEAR(bench.y, hand.y, 1e-9) << x << ", " << y;
            EXPECT_NEAR(bench.z, hand.z, 1e-9) << x << ", " << y;
        }
    }
}

// Lensmaker's equation for a thick lens in air (Hecht, Optics, 5th ed., eq. 6.2).
double singlet_efl() {
    const double power = (kSingletIndex - 1) * (1 / kSingletR1 - 1 / kSingletR2 +
                                                (kSingletIndex - 1) * kSingletThickness /
                                                    (kSingletIndex * kSingletR1 * kSingletR2));
    return 1 / power;
}

TEST(DecentredElements, ParabasalMatricesOfACoaxialSystemAreItsParaxialOnes) {
    const OpticalSystem system = decentred_system(decentred_singlet(json::object()));
    ASSERT_TRUE(system.coaxial());
    const ParaxialResult paraxial = paraxial_trace(system, kLineD);
    const auto m = parabasal_matrices(system, {{0, 0, -10}, {0, 0, 1}}, kLineD);
    ASSERT_TRUE(m);
    // From the plane z = -10 to the last vertex: the paraxial matrix after a transfer of 10.
    EXPECT_NEAR(m->y.a, paraxial.a, 1e-8);
    EXPECT_NEAR(m->y.b, paraxial.b + 10 * paraxial.a, 1e-7);
    EXPECT_NEAR(m->y.c, paraxial.c, 1e-10);
    EXPECT_NEAR(m->y.d, paraxial.d + 10 * paraxial.c, 1e-8);
    EXPECT_NEAR(m->x.c, m->y.c, 1e-10);
    EXPECT_NEAR(m->y.a * m->y.d - m->y.b * m->y.c, 1.0, 1e-8);  // (y, n u) matrices: det 1
    const ParaxialResult p = parabasal_paraxial(system, *m, kLineD);
    EXPECT_NEAR(p.efl, singlet_efl(), 1e-7);
    EXPECT_NEAR(p.efl, paraxial.efl, 1e-7);
    EXPECT_NEAR(p.bfl, paraxial.bfl, 1e-7);
}

FirstOrder decentred_first_order(const OpticalSystem& system) {
    FirstOrderOptions o;
    o.epd = 10;
    o.fields = {0, 2};
    return first_order(system, paraxial_trace(system, kLineD), o);
}

// A decentred element carries its stop (surface 1) with it: the central chief ray is the
// element's own axis, so the parabasal focal length is the centred lens's and the focus
// moves with the element.
TEST(DecentredElements, ADecentredElementKeepsItsFocalLengthAndCarriesItsFocus) {
    const OpticalSystem system =
        decentred_system(decentred_singlet({{"decenter_x", 1.5}, {"decenter_y", -2}}));
    ASSERT_FALSE(system.coaxial());
    const FirstOrder f = decentred_first_order(system);
    ASSERT_TRUE(f.parabasal);
    const FirstOrder centred =
        decentred_first_order(decentred_system(decentred_singlet(json::object())));
    EXPECT_NEAR(f.efl, singlet_efl(), 1e-7);
    EXPECT_NEAR(f.parabasal->efl_x, singlet_efl(), 1e-7);
    EXPECT_NEAR(f.image_position, centred.image_position, 1e-7);
    EXPECT_NEAR(f.parabasal->rear_focus.x, 1.5, 1e-9);
    EXPECT_NEAR(f.parabasal->rear_focus.y, -2, 1e-9);
    EXPECT_NEAR(f.f_number, centred.f_number, 1e-8);
}

// A thin lens met at an angle θ by a ray through its centre (θ' inside): Coddington's
// equations summed over its two faces give the sagittal power φ_s = (n cos θ' - cos θ)
// (1/R1 - 1/R2) and the tangential focus at cos²θ / φ_s along the ray (Smith, Modern Optical
// Engineering, 4th ed., section 5.8; Kingslake, Lens Design Fundamentals, ch. 4). A lens
// 0.05 thick and 2 across is thin to about 1e-3.
TEST(DecentredElements, ATiltedThinLensFocusesItsSectionsAsCoddingtonSays) {
    const double theta = 10 * M_PI / 180;
    const auto thin = [](const json& moves) {
        json scene = decentred_singlet(moves);
        json& element = scene["objects"][0]["elements"][0];
        element["thickness"] = 0.05;
        element["diameter"] = 2;
        return decentred_system(scene);
    };
    FirstOrderOptions o;
    o.epd = 0.5;
    const OpticalSystem tilted = thin({{"tilt_x", 10}});
    const OpticalSystem square = thin(json::object());
    const FirstOrder f = first_order(tilted, paraxial_trace(tilted, kLineD), o);
    const FirstOrder f0 = first_order(square, paraxial_trace(square, kLineD), o);
    ASSERT_TRUE(f.parabasal);
    const double inside = std::asin(std::sin(theta) / kSingletIndex);
    const double n = kSingletIndex;
    // Tilted about x: the y-z section is the tangential one.
    EXPECT_NEAR(f.efl / f.parabasal->efl_x, std::cos(theta) * std::cos(theta), 1e-3);
    EXPECT_NEAR(f.parabasal->efl_x / f0.efl, (n - 1) / (n * std::cos(inside) - std::cos(theta)),
                1e-3);
}

// A cylinder lens (faces curved in y alone, typed as sag formulas in x and y) has the thick
// lens's focal length in its y-z section and no power in x.
TEST(DecentredElements, ACylinderLensFocusesItsCurvedSectionOnly) {
    const auto cylinder = [](double r) {
        return json{{"shape", "sag"},
                    {"formula", std::to_string(r) + " - " + (r > 0 ? "" : "-") + "sqrt(" +
                                    std::to_string(r * r) + " - y^2)"}};
    };
    json scene = decentred_singlet(json::object());
    scene["objects"][0]["elements"][0]["front"] = cylinder(kSingletR1);
    scene["objects"][0]["elements"][0]["back"] = cylinder(kSingletR2);
    const OpticalSystem system = decentred_system(scene);
    ASSERT_FALSE(system.coaxial());
    const FirstOrder f = decentred_first_order(system);
    ASSERT_TRUE(f.parabasal);
    // A typed formula's normal is a central difference: good to a few parts in 1e5 here.
    EXPECT_NEAR(f.efl, singlet_efl(), 1e-4 * singlet_efl());
    EXPECT_GT(std::abs(f.parabasal->efl_x), 1e6 * singlet_efl());
}

TEST(DecentredElements, BiconicAndToroidalCylinderLensesFocusAsTheThickLens) {
    // The same cylinder lens given in closed form (exact normals): the thick lens's EFL in y
    // to 1e-7, none in x. A toroid whose rotation radius equals its curve's is the sphere:
    // the same EFL in both sections.
    const auto biconic = [](double r) {
        return json{{"shape", "biconic"}, {"radius_x", 0}, {"radius_y", r}};
    };
    json scene = decentred_singlet(json::object());
    scene["objects"][0]["elements"][0]["front"] = biconic(kSingletR1);
    scene["objects"][0]["elements"][0]["back"] = biconic(kSingletR2);
    const FirstOrder cylinder = decentred_first_order(decentred_system(scene));
    ASSERT_TRUE(cylinder.parabasal);
    EXPECT_NEAR(cylinder.efl, singlet_efl(), 1e-7);
    EXPECT_GT(std::abs(cylinder.parabasal->efl_x), 1e6 * singlet_efl());

    const auto toroid = [](double r) {
        return json{{"shape", "toroidal"}, {"radius", r}, {"radius_of_rotation", r}};
    };
    scene["objects"][0]["elements"][0]["front"] = toroid(kSingletR1);
    scene["objects"][0]["elements"][0]["back"] = toroid(kSingletR2);
    const FirstOrder sphere = decentred_first_order(decentred_system(scene));
    ASSERT_TRUE(sphere.parabasal);
    EXPECT_NEAR(sphere.efl, singlet_efl(), 1e-7);
    EXPECT_NEAR(sphere.parabasal->efl_x, singlet_efl(), 1e-7);
}

// The thick lens (Hecht eq. 6.2) of front curvature c1, back radius R2, thickness t.
double thick_lens_efl(double c1, double t) {
    const double n = kSingletIndex, c2 = 1 / kSingletR2;
    return 1 / ((n - 1) * (c1 - c2 + (n - 1) * t * c1 * c2 / n));
}

TEST(DecentredElements, ZernikeAndXyPolynomialFacesFocusAsTheirVertexCurvature) {
    // On the front's sphere: Noll Z4 = √3 (2ρ² − 1) adds 4√3 Z4 / R_n² to the vertex curvature
    // and stands the face off its vertex plane by −√3 Z4 (a thicker lens); C x² + C y² (in
    // x / R_n, y / R_n) adds 2C / R_n² and nothing at the vertex.
    const double rn = 10, z4 = 0.01, c = 0.05;
    json scene = decentred_singlet(json::object());
    json& front = scene["objects"][0]["elements"][0]["front"];
    front = {{"shape", "zernike"},
             {"radius", kSingletR1},
             {"normalization_radius", rn},
             {"zernike", {0, 0, 0, z4}}};
    const FirstOrder zernike = decentred_first_order(decentred_system(scene));
    const double z4_efl = thick_lens_efl(1 / kSingletR1 + 4 * std::sqrt(3.0) * z4 / (rn * rn),
                                         kSingletThickness + std::sqrt(3.0) * z4);
    EXPECT_NEAR(zernike.efl, z4_efl, 1e-7 * z4_efl);
    EXPECT_NEAR(zernike.parabasal->efl_x, z4_efl, 1e-7 * z4_efl);

    front = {{"shape", "xy_polynomial"},
             {"radius", kSingletR1},
             {"normalization_radius", rn},
             {"terms", {0, 0, c, 0, c}}};
    const FirstOrder xy = decentred_first_order(decentred_system(scene));
    const double xy_efl = thick_lens_efl(1 / kSingletR1 + 2 * c / (rn * rn), kSingletThickness);
    EXPECT_NEAR(xy.efl, xy_efl, 1e-7 * xy_efl);
    // Only the x² term: the y section keeps the sphere's power.
    front["terms"] = {0, 0, c};
    const FirstOrder x_only = decentred_first_order(decentred_system(scene));
    EXPECT_NEAR(x_only.efl, singlet_efl(), 1e-7 * singlet_efl());
    EXPECT_NEAR(x_only.parabasal->efl_x, xy_efl, 1e-7 * xy_efl);
}

TEST(DecentredElements, TheReportSaysParabasalAndLeavesOutSeidelSums) {
    const OpticalSystem system = decentred_system(decentred_singlet({{"tilt_y", 1}}));
    LensReportOptions options;
    options.first_order.epd = 10;
    const LensReport r = analyze_lens_system(system, options);
    const nlohmann::ordered_json j = report_json(system, r);
    EXPECT_EQ(j["first_order_basis"], "parabasal");
    EXPECT_EQ(j["first_order"]["basis"], "parabasal");
    EXPECT_TRUE(j["seidel"].is_null());
    EXPECT_NE(report_table(system, r, true)
                  .find("not computed for a decentred, tilted or anamorphic system"),
              std::string::npos);
}

TEST(DecentredElements, CementedElementsMoveTogether) {
    json scene = decentred_singlet({{"tilt_x", 2}});
    json& elements = scene["objects"][0]["elements"];
    elements[0].erase("back");
    elements.push_back({{"front", {{"shape", "sphere"}, {"radius", kSingletR2}}},
                        {"back", {{"shape", "flat"}}},
                        {"thickness", 2},
                        {"material", {{"color", 1}, {"transparency", 1}, {"ior", 1.7}}}});
    const OpticalSystem system = decentred_system(scene);
    ASSERT_EQ(system.surfaces.size(), 3u);  // the cemented face is one surface
    for (const SystemSurface& s : system.surfaces) ASSERT_TRUE(s.pose);
    EXPECT_NEAR(system.surfaces[2].z, kSingletThickness + 2, 1e-12);  // as designed
    const Vec3 w = system.surfaces[2].pose->axes.w;
    EXPECT_NEAR(w.y, -std::sin(2 * M_PI / 180), 1e-12);  // +z turned towards -y
    const Vec3 v = system.surfaces[2].pose->vertex;
    EXPECT_NEAR(v.y, w.y * (kSingletThickness + 2), 1e-12);

    elements[1]["tilt_x"] = 1;
    try {
        (void)scene_from_json(scene);
        FAIL() << "a tilt on a cemented element's follower was accepted";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.path(), "objects[0].elements[1]");
        EXPECT_NE(e.reason().find("on the first of them"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace lenslab
