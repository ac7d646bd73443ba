// A `lens` moved from the axis it was designed on (its decenter_x ... tilt_z keys): the bench
// keeps the designed axis and traces the moved lens as it does a lens group's moved element
// (itself checked against an independent trace in test_decentred_elements.cpp).

#include <gtest/gtest.h>

#include "analysis/system/first_order.h"
#include "analysis/system/optical_system.h"
#include "analysis/system/paraxial.h"
#include "analysis/system/real_ray.h"
#include "scene/scene_json.h"
#include "util/scene_error.h"

namespace lenslab {
namespace {

using nlohmann::json;

constexpr double kMovedIndex = 1.5, kMovedR1 = 50, kMovedR2 = -40, kMovedThickness = 5,
                 kMovedDiameter = 25;

json scene_of(const json& objects) {
    return {{"camera", {{"position", {0, 0, -100}}, {"look_at", {0, 0, 0}}}}, {"objects", objects}};
}

json faces() {
    return {{"front", {{"shape", "sphere"}, {"radius", kMovedR1}}},
            {"back", {{"shape", "sphere"}, {"radius", kMovedR2}}},
            {"thickness", kMovedThickness},
            {"material", {{"color", 1}, {"transparency", 1}, {"ior", kMovedIndex}}}};
}

// The singlet as a `lens` whose front vertex is the origin, moved by `moves`, and a second
// lens on the axis 20 behind it.
json moved_lens_pair(const json& moves) {
    json lens = faces();
    lens.update({{"type", "lens"},
                 {"center", {0, 0, 0.5 * kMovedThickness}},
                 {"axis", {0, 0, 1}},
                 {"diameter", kMovedDiameter}});
    lens.update(moves);
    json second = faces();
    second.update({{"type", "lens"},
                   {"center", {0, 0, 30}},
                   {"axis", {0, 0, 1}},
                   {"diameter", kMovedDiameter}});
    return scene_of({lens, second});
}

// The same two lenses as a lens group, its first element moved by `moves`.
json moved_group_pair(const json& moves) {
    json first = faces(), second = faces();
    first.update(moves);
    first["gap"] = 30 - 0.5 * kMovedThickness - kMovedThickness;
    return scene_of({{{"type", "lens_group"},
                      {"vertex", {0, 0, 0}},
                      {"axis", {0, 0, 1}},
                      {"diameter", kMovedDiameter},
                      {"elements", {first, second}}}});
}

OpticalSystem system_of(const json& scene) { return build_optical_system(scene_from_json(scene)); }

TEST(MovedLenses, AMovedLensIsTracedAsTheSameLensGroupElement) {
    const json moves = {{"decenter_x", 0.4},
                        {"decenter_y", -0.3},
                        {"tilt_x", 3.0},
                        {"tilt_y", -2.0},
                        {"tilt_z", 5}};
    const OpticalSystem lens = system_of(moved_lens_pair(moves));
    const OpticalSystem group = system_of(moved_group_pair(moves));
    ASSERT_FALSE(lens.coaxial());
    ASSERT_EQ(lens.surfaces.size(), group.surfaces.size());
    for (const auto& [x, y] : {std::pair{0.0, 0.0}, {5.0, 0.0}, {0.0, -7.0}, {3.3, 8.1}}) {
        const Ray start{{x, y, -10}, normalize(Vec3{0.01, -0.02, 1})};
        const RealRay a = trace_real_ray(lens, start, kLineD);
        const RealRay b = trace_real_ray(group, start, kLineD);
        ASSERT_EQ(a.fate, RayFate::Passed) << x << ", " << y;
        ASSERT_EQ(a.points.size(), b.points.size());
        for (size_t i = 0; i < a.points.size(); ++i) {
            EXPECT_NEAR(length(a.points[i] - b.points[i]), 0, 1e-9) << x << ", " << y << " " << i;
        }
        EXPECT_NEAR(length(a.direction - b.direction), 0, 1e-12);
    }
}

// Rigid translation across a beam parallel to the axis moves its focus by as much: the
// decentred first lens's parabasal rear focus, with the second lens removed, is the centred
// one's moved by the decentre.
TEST(MovedLenses, ADecentredLensCarriesItsFocusAcrossTheDesignedAxis) {
    json scene = moved_lens_pair({{"decenter_x", 1.5}, {"decenter_y", -2}});
    scene["objects"].erase(1);
    FirstOrderOptions o;
    o.epd = 10;
    o.fields = {0, 2};
    const OpticalSystem system = system_of(scene);
    ASSERT_FALSE(system.coaxial());
    const FirstOrder f = first_order(system, paraxial_trace(system, kLineD), o);
    ASSERT_TRUE(f.parabasal);
    EXPECT_NEAR(f.parabasal->rear_focus.x, 1.5, 1e-9);
    EXPECT_NEAR(f.parabasal->rear_focus.y, -2, 1e-9);
    // The system's axis stays the designed one: the lens's vertex is 0 on it.
    EXPECT_NEAR(system.origin.x, 0, 1e-12);
    EXPECT_NEAR(system.origin.y, 0, 1e-12);
}

TEST(MovedLenses, TheReportFormTakesNoDecentre) {
    const json scene = scene_of({{{"type", "lens"},
                                  {"center", {0, 0, 0}},
                                  {"axis", {0, 0, 1}},
                                  {"curvature_radius", 1},
                                  {"aperture_radius", 0.5},
                                  {"tilt_x", 2},
                                  {"material", {{"transparency", 1}, {"ior", 1.5}}}}});
    try {
        (void)scene_from_json(scene);
        FAIL() << "a report-form lens took a tilt";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "objects[0].tilt_x: belongs to the prescription form; the report form "
                  "(curvature_radius, aperture_radius) cannot take it");
    }
}

}  // namespace
}  // namespace lenslab
