// Folded systems on the bench: lens groups with mirrors, the light turning back along the
// axis at each. Every expected value comes from a closed form: the mirror's focal length R/2,
// the exact axial crossing of a ray reflected by a sphere, the spherical aberration of a
// conic mirror in proportion to (1 + k), the Cassegrain and Ritchey-Chretien formulas, the
// Schmidt corrector's fourth-order profile, Paul's three-mirror anastigmat.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "analysis/aberrations/aberrations.h"
#include "analysis/aberrations/seidel.h"
#include "analysis/system/field_beam.h"
#include "analysis/system/first_order.h"
#include "analysis/system/optical_system.h"
#include "analysis/system/paraxial.h"
#include "analysis/system/real_ray.h"
#include "geometry/lens/lens_solid.h"
#include "optics/refraction.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

std::string number(double v) {
    std::ostringstream s;
    s.precision(17);
    s << v;
    return s.str();
}

std::string conic(double radius, double k) {
    return R"({"shape": "conic", "radius": )" + number(radius) + R"(, "k": )" + number(k) + "}";
}

std::string mirror(const std::string& surface, double diameter, double gap, double hole = 0) {
    return R"({"mirror": )" + surface + R"(, "diameter": )" + number(diameter) + R"(, "gap": )" +
           number(gap) + R"(, "hole_diameter": )" + number(hole) +
           R"(, "material": {"color": 0, "specular": 1}})";
}

Scene group_scene(const std::string& elements, double diameter) {
    return parse_scene(R"({"objects": [{"type": "lens_group", "name": "telescope",
        "vertex": [0, 0, 0], "axis": [0, 0, 1], "diameter": )" +
                           number(diameter) + R"(, "elements": [)" + elements + "]}]}",
                       "test", "", {.require_camera = false});
}

FirstOrder first_order_at(const OpticalSystem& system, int stop, double epd,
                          std::vector<double> fields = {0}) {
    FirstOrderOptions o;
    o.wavelength_nm = kLineD;
    o.stop = stop;
    o.epd = epd;
    o.fields = std::move(fields);
    return first_order(system, paraxial_trace(system, kLineD), o);
}

// A concave sphere of radius R facing the light focuses at R/2 in front of it.
TEST(FoldedSystem, AConcaveMirrorFocusesAtHalfItsRadiusInFrontOfIt) {
    const Scene scene = group_scene(mirror(conic(-200, 0), 40, 100), 40);
    const OpticalSystem system = build_optical_system(scene);
    ASSERT_EQ(system.surfaces.size(), 1u);
    EXPECT_TRUE(system.surfaces[0].mirror);
    EXPECT_EQ(system.image_travel(), -1.0);
    EXPECT_EQ(system.n_after(0, kLineD), -1.0);
    const ParaxialResult p = paraxial_trace(system, kLineD);
    EXPECT_NEAR(p.efl, 100.0, 1e-12);
    EXPECT_NEAR(p.bfl, -100.0, 1e-12);  // signed along the axis, as Zemax writes it
    EXPECT_NEAR(p.z_rear_focus, -100.0, 1e-12);
}

// A ray parallel to the axis at height h meets a sphere of radius R where sin(theta) = h/R
// and, reflected, crosses the axis R / (2 cos(theta)) from the centre of curvature.
TEST(FoldedSystem, ARayReflectedByASphereCrossesTheAxisWhereGeometrySays) {
    const double R = 200.0;
    const Scene scene = group_scene(mirror(conic(-R, 0), 120, 100), 120);
    const OpticalSystem system = build_optical_system(scene);
    for (double h : {5.0, 30.0, 55.0}) {
        const RealRay r = trace_real_ray(system, {{0, h, -50}, {0, 0, 1}}, kLineD);
        ASSERT_EQ(r.fate, RayFate::Passed);
        ASSERT_LT(r.direction.z, 0.0);
        const double z_cross = r.exit_point().z - r.exit_point().y * r.direction.z / r.direction.y;
        const double theta = std::asin(h / R);
        EXPECT_NEAR(z_cross, -R + R / (2.0 * std::cos(theta)), 1e-10) << "h " << h;
    }
}

// The third-order spherical aberration of a conic mirror with the stop on it is that of the
// sphere times (1 + k) (Schroeder, Astronomical Optics, 2nd ed., section 5.3): none for the
// paraboloid, whose real rays all meet at its focus.
TEST(FoldedSystem, AConicMirrorsSphericalAberrationScalesWithOnePlusK) {
    const double R = -400.0;
    const auto s1 = [&](double k) {
        const Scene scene = group_scene(mirror(conic(R, k), 100, 150), 100);
        const OpticalSystem system = build_optical_system(scene);
        return seidel_sums(system, first_order_at(system, 0, 100), kLineF, kLineC).total.spherical;
    };
    const double sphere = s1(0.0);
    EXPECT_NE(sphere, 0.0);
    // For the sphere, S_I = -2 y^4 c^3 with y the marginal height 50 and c = 1/R.
    EXPECT_NEAR(sphere, -2.0 * std::pow(50.0, 4) / std::pow(R, 3), 1e-12);
    for (double k : {-1.0, -0.5, -2.3, 0.7}) {
        EXPECT_NEAR(s1(k), sphere * (1.0 + k), 1e-12 * std::abs(sphere)) << "k " << k;
    }

    const Scene paraboloid = group_scene(mirror(conic(R, -1), 100, 150), 100);
    const OpticalSystem system = build_optical_system(paraboloid);
    int lost = 0;
    const auto rays = trace_collimated_beam(system, kLineD, 50.0, 8, &lost);
    EXPECT_EQ(lost, 0);
    const SpotDiagram spot = spot_at(rays, R / 2);
    EXPECT_LT(spot.geometric_radius, 1e-11);
}

// A two-mirror telescope of focal length F, mirrors D apart and the focus B behind the
// secondary: R1 = -2 D F / (F - B), R2 = -2 D B / (F - B - D), M = (F - B) / D. Conics: the
// classical Cassegrain's paraboloid primary, or the Ritchey-Chretien's two hyperboloids
// K1 = -1 - 2 B / (D M^3), K2 = -1 - 2 (M (2 M - 1) + B / D) / (M - 1)^3, free of
// third-order spherical aberration and coma (Schroeder, Astronomical Optics, 2nd ed.,
// section 6.2; the same formulas in Wilson, Reflecting Telescope Optics I, section 3.2).
struct TwoMirror {
    double F = 2000, D = 500, B = 700, aperture = 250;
    double M() const { return (F - B) / D; }
    double R1() const { return -2 * D * F / (F - B); }
    double R2() const { return -2 * D * B / (F - B - D); }
    double K1_rc() const { return -1 - 2 * B / (D * std::pow(M(), 3)); }
    double K2_rc() const { return -1 - 2 * (M() * (2 * M() - 1) + B / D) / std::pow(M() - 1, 3); }
    Scene scene(double k1, double k2) const {
        return group_scene(
            mirror(conic(R1(), k1), aperture, D, 60) + "," + mirror(conic(R2(), k2), 70, B),
            aperture);
    }
};

TEST(FoldedSystem, TheCassegrainsFocalLengthIsTheFormulas) {
    const TwoMirror t;
    const OpticalSystem system = build_optical_system(t.scene(-1, 0));
    ASSERT_EQ(system.surfaces.size(), 2u);
    EXPECT_EQ(system.image_travel(), 1.0);  // twice reflected: along the axis again
    const ParaxialResult p = paraxial_trace(system, kLineD);
    EXPECT_NEAR(p.efl, t.F, 1e-6);
    // The focus B behind the secondary: B - D behind the primary's vertex.
    EXPECT_NEAR(p.z_rear_focus, t.B - t.D, 1e-6);
    const FirstOrder f = first_order_at(system, 0, t.aperture);
    EXPECT_NEAR(f.f_number, t.F / t.aperture, 1e-6);
}

TEST(FoldedSystem, TheRitcheyChretienIsFreeOfSphericalAberrationAndComa) {
    const TwoMirror t;
    const OpticalSystem rc = build_optical_system(t.scene(t.K1_rc(), t.K2_rc()));
    const SeidelSums s =
        seidel_sums(rc, first_order_at(rc, 0, t.aperture, {0.2}), kLineF, kLineC).total;
    const OpticalSystem cassegrain =
        build_optical_system(t.scene(-1, -std::pow((t.M() + 1) / (t.M() - 1), 2)));
    const SeidelSums c =
        seidel_sums(cassegrain, first_order_at(cassegrain, 0, t.aperture, {0.2}), kLineF, kLineC)
            .total;
    // The classical Cassegrain (its secondary the hyperboloid that images the primary's focus
    // perfectly) has no spherical aberration but the coma of the paraboloid.
    EXPECT_NEAR(c.spherical, 0.0, 1e-12);
    EXPECT_GT(std::abs(c.coma), 1e-6);
    EXPECT_NEAR(s.spherical, 0.0, 1e-9 * std::abs(c.coma));
    EXPECT_NEAR(s.coma, 0.0, 1e-9 * std::abs(c.coma));

    // Real rays across the field: the classical Cassegrain's blur is coma, linear in the
    // field angle; the aplanat's is astigmatism, quadratic (Schroeder, section 6.2), and far
    // smaller at small fields.
    const auto rms = [](const OpticalSystem& system, double field) {
        const FirstOrder f = first_order_at(system, 0, 250, {field});
        const FieldBeam beam = trace_field_beam(system, f, field, kLineD, 8);
        return spot_at(beam.rays, best_focus_z(beam.rays, system.last_vertex() + f.image_position))
            .rms_radius;
    };
    const double classical_ratio = rms(cassegrain, 0.1) / rms(cassegrain, 0.05);
    const double aplanat_ratio = rms(rc, 0.1) / rms(rc, 0.05);
    std::printf("RMS at 0.1 / at 0.05 degrees: Cassegrain %.4f, Ritchey-Chretien %.4f\n",
                classical_ratio, aplanat_ratio);
    EXPECT_NEAR(classical_ratio, 2.0, 0.1);
    EXPECT_NEAR(aplanat_ratio, 4.0, 0.4);
    EXPECT_LT(rms(rc, 0.05), 0.1 * rms(cassegrain, 0.05));
    EXPECT_LT(rms(rc, 0.0), 1e-3);  // mm, against an Airy radius of 5.7 micrometres
}

// A Schmidt camera: a sphere of radius R with a thin plate at its centre of curvature, the
// plate's fourth-order profile A4 r^4 cancelling the sphere's spherical aberration,
// |A4| = |c|^3 / (4 (n - 1)) (Schroeder, Astronomical Optics, 2nd ed., section 7.2: the plate
// z = r^4 / (4 (n - 1) R^3)); with the stop and the aspheric face at the centre of curvature,
// the sphere has no coma or astigmatism either. The aspheric face is the plate's back (glass
// to air, so its sign is the front's turned) typed as a sag formula; flat on the axis, the
// plate leaves the focal length R / 2.
TEST(FoldedSystem, TheSchmidtCamerasPlateCancelsTheSpheresAberrations) {
    const double R = -200.0, n = 1.5;
    const double c = 1.0 / R;
    const double A4 = -c * c * c / (4.0 * (n - 1.0));
    const auto scene = [&](bool plate) {
        const std::string back = plate
                                     ? R"({"shape": "sag", "formula": ")" + number(A4) + R"(*r^4"})"
                                     : R"({"shape": "flat"})";
        return group_scene(R"({"front": {"shape": "flat"}, "back": )" + back + R"(,
            "thickness": 5, "gap": 200, "diameter": 60,
            "material": {"transparency": 1, "ior": 1.5}},)" +
                               mirror(conic(R, 0), 100, 100),
                           60);
    };
    const OpticalSystem schmidt = build_optical_system(scene(true));
    ASSERT_EQ(schmidt.surfaces.size(), 3u);
    EXPECT_NEAR(schmidt.surfaces[1].a4, A4, 1e-9 * std::abs(A4));
    const ParaxialResult p = paraxial_trace(schmidt, kLineD);
    EXPECT_NEAR(p.efl, -R / 2, 1e-9);
    EXPECT_NEAR(p.z_rear_focus, 205.0 + R / 2, 1e-9);
    const FirstOrder f = first_order_at(schmidt, 1, 50, {3.0});
    EXPECT_NEAR(f.f_number, 2.0, 1e-9);
    const SeidelSums s = seidel_sums(schmidt, f, kLineF, kLineC).total;
    const OpticalSystem bare = build_optical_system(scene(false));
    const SeidelSums b =
        seidel_sums(bare, first_order_at(bare, 1, 50, {3.0}), kLineF, kLineC).total;
    EXPECT_GT(std::abs(b.spherical), 1e-4);
    EXPECT_NEAR(s.spherical, 0.0, 1e-9 * std::abs(b.spherical));
    EXPECT_NEAR(s.coma, 0.0, 1e-9 * std::abs(b.spherical));
    EXPECT_NEAR(s.astigmatism, 0.0, 1e-9 * std::abs(b.spherical));
    EXPECT_NE(s.petzval, 0.0);  // the Schmidt's curved field

    // Real rays: what the plate leaves at F/2 is fifth-order, a small part of the sphere's blur.
    const auto rms = [&](const OpticalSystem& system) {
        int lost = 0;
        const auto rays = trace_collimated_beam(system, kLineD, 25.0, 8, &lost);
        EXPECT_EQ(lost, 0);
        return spot_at(rays, best_focus_z(rays, p.z_rear_focus)).rms_radius;
    };
    const double with_plate = rms(schmidt), without = rms(bare);
    EXPECT_LT(with_plate, 0.1 * without) << with_plate << " against " << without;
}

// Paul's three-mirror anastigmat (M. Paul, Rev. d'Optique 14, 1935; Wilson, Reflecting
// Telescope Optics I, 2nd ed., section 3.6.5; Korsch, Reflective Optics, section 8.2): a
// paraboloid primary and a convex spherical secondary confocal with it (an afocal Mersenne
// pair, the beam compressed F1 / f2), then a concave spherical tertiary of the secondary's
// radius with its centre of curvature on the secondary, which carries the stop. The tertiary's
// spherical aberration cancels the secondary's departure from a paraboloid, and with the
// stop at its centre of curvature it adds no coma or astigmatism: S_I = S_II = S_III = 0, the
// field curved. EFL = f3 F1 / f2. Here F1 = 1000, f2 = f3 = 400: EFL 1000, at EPD 200 F/5.
TEST(FoldedSystem, PaulsThreeMirrorAnastigmatHasNoSphericalComaOrAstigmatism) {
    const double F1 = 1000, f2 = 400;
    const double R2 = -2 * f2;  // convex towards the primary: its centre beyond it
    const double d = F1 - f2;   // confocal
    const OpticalSystem paul = build_optical_system(
        group_scene(mirror(conic(-2 * F1, -1), 220, d, 90) + "," + mirror(conic(R2, 0), 90, -R2) +
                        "," + mirror(conic(R2, 0), 100, 0),
                    220));
    ASSERT_EQ(paul.surfaces.size(), 3u);
    const double f3 = -R2 / 2;        // the tertiary has the secondary's radius
    const double efl = f3 * F1 / f2;  // its focal length times the compression
    const ParaxialResult p = paraxial_trace(paul, kLineD);
    EXPECT_NEAR(p.efl, efl, 1e-6);
    EXPECT_NEAR(p.z_rear_focus, -d - R2 + R2 / 2, 1e-6);  // f3 in front of the tertiary
    const FirstOrder f = first_order_at(paul, 1, 200, {0.2});
    EXPECT_NEAR(f.f_number, efl / 200, 1e-6);
    const Seidel seidel = seidel_sums(paul, f, kLineF, kLineC);
    const double scale = std::abs(seidel.surfaces[1].spherical);  // the secondary's alone
    EXPECT_GT(scale, 1e-3);
    EXPECT_NEAR(seidel.total.spherical, 0.0, 1e-9 * scale);
    EXPECT_NEAR(seidel.total.coma, 0.0, 1e-9 * scale);
    EXPECT_NEAR(seidel.total.astigmatism, 0.0, 1e-9 * scale);
    EXPECT_GT(std::abs(seidel.total.petzval), 1e-5);  // Paul's curved field
    // Real rays across the field: well inside the Airy radius 1.22 lambda N.
    const double airy = 1.22 * kLineD * 1e-6 * f.f_number;
    for (double field : {0.0, 0.2}) {
        const FieldBeam beam = trace_field_beam(paul, f, field, kLineD, 6);
        EXPECT_GT(beam.rays.size(), 100u) << field;
        const SpotDiagram spot = spot_at(beam.rays, p.z_rear_focus);
        EXPECT_LT(spot.rms_radius, 0.1 * airy) << field;
    }
}

// An independent trace through the scene as it stands in space (Scene::intersect, the law
// of reflection at mirrors, Snell's law in and out of the constant-index lenses): where the
// ray goes when nothing is straightened or sequenced.
struct WorldRay {
    Vec3 point, direction;
    int hits = 0;
};

WorldRay trace_in_space(const Scene& scene, Vec3 p, Vec3 d) {
    WorldRay out;
    SceneHit hit;
    int inside = -1;  // the lens the ray is in
    while (scene.intersect({p, d}, 1e-9, INFINITY, hit)) {
        ++out.hits;
        p = hit.surface.point;
        const Vec3& n = hit.surface.normal;
        if (scene.objects[hit.object].type == ObjectType::Mirror) {
            d = reflect(d, n);
            continue;
        }
        const double glass = scene.material_of(hit.object).index->n(kLineD);
        const bool entering = inside < 0;
        const auto bent = refract(d, entering ? n : -n, entering ? 1.0 / glass : glass);
        if (!bent) break;
        d = *bent;
        inside = entering ? hit.object : -1;
    }
    out.point = p;
    out.direction = d;
    return out;
}

std::string lens(double r1, double r2, double thickness, double gap) {
    return R"({"front": )" + conic(r1, 0) + R"(, "back": )" + conic(r2, 0) + R"(, "thickness": )" +
           number(thickness) + R"(, "gap": )" + number(gap) +
           R"(, "diameter": 20, "material": {"transparency": 1, "ior": 1.5}})";
}

std::string fold(double gap, double tilt_x) {
    return R"({"mirror": {"shape": "flat"}, "tilt_x": )" + number(tilt_x) + R"(, "gap": )" +
           number(gap) + R"(, "diameter": 40, "material": {"color": 0, "specular": 1}})";
}

// A flat mirror at 45 degrees between two lenses turns the axis by 90 degrees; the bench
// measures the folded system as the straight one, and the rays through the scene as it
// stands in space agree. Behind the mirror light travels against the turned axis, so the
// second lens's radii change sign, as in a Zemax file.
TEST(FoldedSystem, AFoldMirrorBetweenTwoLensesGivesTheStraightSystemsSpots) {
    const Scene straight = group_scene(lens(50, -50, 5, 50) + "," + lens(80, -80, 4, 40), 20);
    const Scene folded =
        group_scene(lens(50, -50, 5, 20) + "," + fold(30, 45) + "," + lens(-80, 80, 4, 40), 20);
    // In space the second lens stands 30 along +y from the mirror, its axis along y.
    const auto& second = dynamic_cast<const LensSolid&>(*folded.objects[2].shape).prescription();
    EXPECT_NEAR(second.centre.y, 32.0, 1e-12);
    EXPECT_NEAR(second.centre.z, 25.0, 1e-12);
    EXPECT_NEAR(std::abs(second.axis.y), 1.0, 1e-15);

    const OpticalSystem a = build_optical_system(straight);
    const OpticalSystem b = build_optical_system(folded);
    ASSERT_EQ(b.surfaces.size(), 5u);
    const ParaxialResult pa = paraxial_trace(a, kLineD), pb = paraxial_trace(b, kLineD);
    EXPECT_NEAR(pb.efl, pa.efl, 1e-9 * pa.efl);
    EXPECT_NEAR(pb.bfl, -pa.bfl, 1e-9 * pa.efl);  // signed along the straightened axis
    for (double field : {0.0, 1.5}) {
        const FirstOrder fa = first_order_at(a, 0, 12, {field});
        const FirstOrder fb = first_order_at(b, 0, 12, {field});
        const double za = a.last_vertex() + fa.image_position;
        const double zb = b.last_vertex() + fb.image_position;
        const SpotDiagram sa = spot_at(trace_field_beam(a, fa, field, kLineD, 6).rays, za);
        const SpotDiagram sb = spot_at(trace_field_beam(b, fb, field, kLineD, 6).rays, zb);
        SCOPED_TRACE(field);
        ASSERT_EQ(sa.points.size(), sb.points.size());
        EXPECT_NEAR(sb.rms_radius, sa.rms_radius, 1e-9 * sa.rms_radius + 1e-12);
        EXPECT_NEAR(sb.centroid_y, sa.centroid_y, 1e-9);
        for (size_t k = 0; k < sa.points.size(); ++k) {
            EXPECT_NEAR(sb.points[k].x, sa.points[k].x, 1e-9);
            EXPECT_NEAR(sb.points[k].y, sa.points[k].y, 1e-9);
        }
    }

    // Through the scene in space: a ray 4 above the axis leaves the second lens heading up
    // (+y) and crosses the turned axis (x = 0, z = 25) as far past the lens, and as steeply,
    // as the bench's ray crosses the straight axis.
    const RealRay r = trace_real_ray(b, {{0, 4, -10}, {0, 0, 1}}, kLineD);
    ASSERT_EQ(r.fate, RayFate::Passed);
    const double bench_cross = r.exit_point().z - r.exit_point().y * r.direction.z / r.direction.y;
    const WorldRay w = trace_in_space(folded, {0, 4, -10}, {0, 0, 1});
    EXPECT_EQ(w.hits, 5);
    ASSERT_GT(w.direction.y, 0.0);
    const double t = (25.0 - w.point.z) / w.direction.z;
    const double world_cross = w.point.y + t * w.direction.y;
    // The straightened last vertex lies at z = b.last_vertex(); in space at y = 34 (mirror at
    // z 25, 30 along +y to the lens, 4 thick).
    EXPECT_NEAR(world_cross - 34.0, -(bench_cross - b.last_vertex()), 1e-9);
    EXPECT_NEAR(std::abs(w.direction.z / w.direction.y), std::abs(r.direction.y / r.direction.z),
                1e-12);
}

// A Newtonian telescope: a paraboloid of focal length 1000 (F/5) and a flat diagonal at 45
// degrees 850 in front of it, the focus turned 150 out to the side. The paraboloid's focus is
// perfect on the axis: the spot far inside the Airy radius 1.22 lambda N (diffraction-
// limited), and every ray meets at the one point in space the geometry puts the focus at.
TEST(FoldedSystem, ANewtoniansFocusIsDiffractionLimitedOnTheAxisAndOutToTheSide) {
    const Scene newtonian =
        group_scene(mirror(conic(-2000, -1), 200, 850) + "," +
                        R"({"mirror": {"shape": "flat"}, "tilt_x": -45, "gap": 150,
                            "diameter": 60, "material": {"color": 0, "specular": 1}})",
                    200);
    const OpticalSystem system = build_optical_system(newtonian);
    const ParaxialResult p = paraxial_trace(system, kLineD);
    EXPECT_NEAR(p.efl, 1000.0, 1e-6);
    // Straightened: the diagonal at z = -850 sends the light back along +z, 150 to the focus.
    EXPECT_NEAR(p.z_rear_focus, -700.0, 1e-9);
    const FirstOrder f = first_order_at(system, 0, 200);
    EXPECT_NEAR(f.f_number, 5.0, 1e-6);
    const SpotDiagram spot = spot_at(trace_field_beam(system, f, 0.0, kLineD, 8).rays, -700.0);
    const double airy = 1.22 * kLineD * 1e-6 * 5.0;
    EXPECT_LT(spot.geometric_radius, 1e-6 * airy);

    // In space the focus is at (0, 150, -850): the diagonal sends the light up (+y).
    for (double h : {20.0, 60.0, 99.0}) {
        const WorldRay w = trace_in_space(newtonian, {0, h, -100}, {0, 0, 1});
        ASSERT_EQ(w.hits, 2);
        const double t = (150.0 - w.point.y) / w.direction.y;
        const Vec3 at = w.point + w.direction * t;
        EXPECT_NEAR(at.x, 0.0, 1e-9) << h;
        EXPECT_NEAR(at.z, -850.0, 1e-9) << h;
    }
}

}  // namespace
}  // namespace lenslab
