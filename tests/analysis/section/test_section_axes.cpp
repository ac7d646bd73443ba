// The section view of a mirror, like a lens's, is cut through its axis and shows a beam along
// it: scenes/paraboloid_mirror.json's paraboloid (vertex (-0.8, 0.2, 0), facing +y, R = 2,
// k = -1) reflects every ray of a beam along its axis through its focus R/2 in front of the
// vertex, (-0.8, 1.2, 0), without spherical aberration (the parabola's focal property).

#include <gtest/gtest.h>

#include <cmath>

#include "analysis/section/section_view.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

TEST(SectionAxes, AParaboloidsBeamMeetsAtItsFocus) {
    const Scene scene = load_scene_file(LENSLAB_SOURCE_DIR "/scenes/paraboloid_mirror.json");
    const int mirror = 0;
    ASSERT_TRUE(section_plane_follows_axis(scene, mirror));
    const SectionPlane plane = default_section_plane(scene, mirror);
    // The plane holds the axis (+y) and the vertex.
    EXPECT_NEAR(dot(plane.normal(), Vec3{0, 1, 0}), 0, 1e-12);
    EXPECT_NEAR(plane.distance({-0.8, 0.2, 0}), 0, 1e-12);

    SectionViewOptions options;
    options.rays.beam = default_section_beam(scene, mirror, plane, 9);
    ASSERT_TRUE(options.rays.beam);
    EXPECT_NEAR(options.rays.beam->direction.y, -1, 1e-12);  // onto the face
    options.rays.rays_per_light = 0;
    const SectionView view = make_section_view(scene, plane, options);
    const Vec3 focus{-0.8, 1.2, 0};
    int through_focus = 0;
    for (const SectionRayPath& r : view.rays) {
        if (r.points.size() < 3 || r.hits.empty() || r.hits[0].object != mirror) continue;
        // The reflected segment's line passes through the focus.
        const Vec3 a = r.points[1], d = normalize(r.points[2] - r.points[1]);
        const Vec3 to_focus = focus - a;
        EXPECT_LT(length(to_focus - d * dot(to_focus, d)), 1e-9);
        ++through_focus;
    }
    EXPECT_GE(through_focus, 8);  // all but the ray along the axis through the vertex
}

}  // namespace
}  // namespace lenslab
