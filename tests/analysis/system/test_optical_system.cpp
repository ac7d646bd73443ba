// Building a coaxial system from a scene: order along the axis, cemented surfaces merged,
// reversed lenses, and the refusals (no lens, off the axis, overlapping, opaque, not a
// surface of revolution), each naming the object.

#include <gtest/gtest.h>

#include <cmath>

#include "../lens_scene_builder.h"
#include "analysis/system/optical_system.h"
#include "analysis/system/paraxial.h"

namespace lenslab {
namespace {

using test::lens_scene;
using test::LensSpec;
using test::sphere;

// Expects build_optical_system to refuse with this path and a reason containing `words`.
void expect_refused(const Scene& scene, const std::string& path, const std::string& words,
                    std::optional<int> lens = {}) {
    try {
        build_optical_system(scene, lens);
        FAIL() << "not refused";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.path(), path) << e.what();
        EXPECT_NE(e.reason().find(words), std::string::npos) << e.what();
    }
}

const LensSpec kCrown{"crown", 0, 4, 25.4, sphere(62.8), sphere(-45.7), test::glass("N-BK7")};
const LensSpec kFlint{"flint", 4, 2.5, 25.4, sphere(-45.7), sphere(-128.2), test::glass("SF5")};

TEST(OpticalSystem, CementedSurfacesBecomeOneGlassToGlassInterface) {
    const OpticalSystem s = build_optical_system(lens_scene({kCrown, kFlint}));
    ASSERT_EQ(s.surfaces.size(), 3u);
    ASSERT_EQ(s.elements.size(), 2u);
    EXPECT_TRUE(s.surfaces[1].cemented());
    EXPECT_EQ(s.surfaces[1].label, "objects[0].back = objects[1].front");
    EXPECT_DOUBLE_EQ(s.surfaces[1].z, 4.0);
    // n on each side of the shared surface are the two glasses' catalogue indices.
    EXPECT_DOUBLE_EQ(s.n_before(1, kLineD), find_glass("N-BK7")->model->n(kLineD));
    EXPECT_DOUBLE_EQ(s.n_after(1, kLineD), find_glass("SF5")->model->n(kLineD));
    EXPECT_DOUBLE_EQ(s.n_before(0, kLineD), 1.0);
    EXPECT_DOUBLE_EQ(s.n_after(2, kLineD), 1.0);
    EXPECT_EQ(s.elements[1].first_surface, 1);
    EXPECT_EQ(s.elements[1].glass, "SF5");
}

TEST(OpticalSystem, AnAirGapKeepsFourSurfaces) {
    LensSpec flint = kFlint;
    flint.z_front = 4.01;
    const OpticalSystem s = build_optical_system(lens_scene({kCrown, flint}));
    ASSERT_EQ(s.surfaces.size(), 4u);
    EXPECT_FALSE(s.surfaces[1].cemented());
    EXPECT_DOUBLE_EQ(s.n_after(1, kLineD), 1.0);
}

TEST(OpticalSystem, LensesAreOrderedAlongTheAxisAndOthersIgnored) {
    // Written last-first, with a triangle between: the system starts at the crown.
    const std::string triangle =
        R"({"type": "triangle", "name": "screen", "vertices": [[0, 0, 90], [1, 0, 90], [0, 1, 90]],
            "material": {"color": 0.5}})";
    LensSpec crown = kCrown, flint = kFlint;
    crown.z_front = 20;
    flint.z_front = 24;
    const Scene scene = lens_scene({flint, crown}, {triangle});
    const OpticalSystem s = build_optical_system(scene);
    ASSERT_EQ(s.elements.size(), 2u);
    EXPECT_EQ(s.elements[0].path, "objects[1]");
    EXPECT_EQ(s.elements[0].name, "crown");
    EXPECT_DOUBLE_EQ(s.surfaces[0].z, 0.0);
    EXPECT_NEAR(s.origin.z, 20.0, 1e-12);
    ASSERT_EQ(s.ignored.size(), 1u);
    EXPECT_EQ(s.ignored[0], "objects[2] ('screen'): not a lens");
}

TEST(OpticalSystem, AReversedLensIsTheSameLensTurnedAround) {
    // A plano-convex lens written with axis +z (flat front, convex back R = -30) and the
    // same solid written with axis -z (its front is then the convex face, R = +30): behind
    // a first lens, both give the same system.
    const LensSpec first{"first", 0, 3, 20, sphere(60), sphere(-60), test::glass("N-BK7")};
    LensSpec forward{"pcx", 10, 4, 20, sphere(0), sphere(-30), test::glass("N-BK7")};
    LensSpec reversed = forward;
    reversed.axis = "[0, 0, -1]";
    reversed.front = sphere(30);
    reversed.back = sphere(0);
    const OpticalSystem a = build_optical_system(lens_scene({first, forward}));
    const OpticalSystem b = build_optical_system(lens_scene({first, reversed}));
    ASSERT_EQ(a.surfaces.size(), b.surfaces.size());
    for (size_t i = 0; i < a.surfaces.size(); ++i) {
        EXPECT_NEAR(a.surfaces[i].z, b.surfaces[i].z, 1e-12);
        EXPECT_NEAR(a.surfaces[i].curvature, b.surfaces[i].curvature, 1e-15);
        for (double r : {0.0, 5.0, 10.0}) {
            EXPECT_NEAR(a.surfaces[i].z_at(r), b.surfaces[i].z_at(r), 1e-12);
        }
    }
    // Light meets the reversed lens's back first.
    EXPECT_EQ(b.surfaces[2].label, "objects[1].back");
    EXPECT_EQ(b.surfaces[3].label, "objects[1].front");
    EXPECT_NEAR(paraxial_trace(a, kLineD).bfl, paraxial_trace(b, kLineD).bfl, 1e-12);
}

TEST(OpticalSystem, RefusesWhatIsNotOneCoaxialLensSystem) {
    const std::string triangle =
        R"({"type": "triangle", "vertices": [[0, 0, 9], [1, 0, 9], [0, 1, 9]], "material": {"color": 0.5}})";
    expect_refused(lens_scene({}, {triangle}), "objects", "no lens in the scene");

    LensSpec off = kFlint;
    off.z_front = 30;
    off.offset_x = 0.5;
    expect_refused(lens_scene({kCrown, off}), "objects[1]",
                   "not on the axis of objects[0] ('crown'): its centre lies 0.5 from that axis");
    LensSpec tilted = kFlint;
    tilted.z_front = 30;
    tilted.axis = "[0, 0.1, 1]";
    expect_refused(lens_scene({kCrown, tilted}), "objects[1]",
                   "its axis is tilted by 5.71059 degrees");

    LensSpec overlapping = kFlint;
    overlapping.z_front = 3;
    expect_refused(lens_scene({kCrown, overlapping}), "objects[1]",
                   "overlaps objects[0] along the axis");

    LensSpec opaque = kCrown;
    opaque.material = R"({"color": 0.5})";
    expect_refused(lens_scene({opaque}), "objects[0].material", "transparency is 0");
}

// A freeform face is measured, about the chief ray: its surfaces placed by the lens's frame.
TEST(OpticalSystem, ALensWithAFreeformFaceIsPlacedByItsOwnFrame) {
    LensSpec saddle = kCrown;
    saddle.front = R"({"shape": "sag", "formula": "(x^2 - y^2) / 200"})";
    const OpticalSystem s = build_optical_system(lens_scene({saddle}));
    EXPECT_FALSE(s.coaxial());
    ASSERT_TRUE(s.surfaces[0].pose);
    EXPECT_NEAR(s.surfaces[0].curvature, -1.0 / 100, 1e-9);  // the y-z section's, as designed
}

TEST(OpticalSystem, AChosenLensTakesOnlyTheLensesOnItsAxis) {
    LensSpec other = kFlint;
    other.z_front = 30;
    other.offset_x = 40;
    const Scene scene = lens_scene({kCrown, other});
    const OpticalSystem s = build_optical_system(scene, 1);
    ASSERT_EQ(s.elements.size(), 1u);
    EXPECT_EQ(s.elements[0].path, "objects[1]");
    ASSERT_EQ(s.ignored.size(), 1u);
    EXPECT_NE(s.ignored[0].find("objects[0] ('crown'): not on the axis of objects[1]"),
              std::string::npos);
    expect_refused(lens_scene({kCrown}, {R"({"type": "sphere", "center": [0, 0, 50], "radius": 1,
                                           "material": {"color": 0.5}})"}),
                   "objects[1]", "is not a lens", 1);
}

TEST(OpticalSystem, WavelengthsOutsideAGlassRangeAreRefused) {
    const OpticalSystem s = build_optical_system(lens_scene({kCrown, kFlint}));
    EXPECT_NO_THROW(check_wavelength(s, 1064.0, "--wavelength"));
    try {
        check_wavelength(s, 350.0, "--wavelength");  // SF5 is published from 370 nm
        FAIL() << "not refused";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.path(), "objects[1].material");
        EXPECT_EQ(e.reason(),
                  "--wavelength 350 nm is outside the validity range 370-2500 nm of SF5");
    }
}

}  // namespace
}  // namespace lenslab
