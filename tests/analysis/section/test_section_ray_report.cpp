// A clicked ray's read-out in the section view: the beam of scenes/prism.json crosses an
// equilateral prism of n = 1.5 at minimum deviation (Hecht, Optics, 5th ed., 5.5.1): it meets
// the first face at asin(1.5 sin 30°) = 48.59°, refracts to 30°, leaves symmetrically and is
// turned D = 2 asin(n sin(A/2)) - A = 37.18° in all.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "analysis/section/section_ray_report.h"
#include "analysis/section/section_view.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

constexpr double kDegree = std::numbers::pi / 180;

TEST(SectionRayReport, APrismAtMinimumDeviationReadsAsHecht) {
    const Scene scene = load_scene_file(LENSLAB_SOURCE_DIR "/scenes/prism.json");
    const SectionPlane plane{{0, 0, 0}, {1, 0, 0}, {0, 0, -1}};  // the beam's plane, y = 0
    const SectionView view = make_section_view(scene, plane);
    const double incidence = std::asin(1.5 * std::sin(30 * kDegree)) / kDegree;
    const double deviation = 2 * incidence - 60;
    int checked = 0;
    for (const SectionRayPath& path : view.rays) {
        if (path.weight < 0.5) continue;  // the faint reflections
        const SectionRayReport r = section_ray_report(scene, path);
        ASSERT_EQ(r.steps.size(), 2u);
        for (const SectionRayStep& s : r.steps) {
            EXPECT_EQ(s.object_name, "prism");
            EXPECT_EQ(s.event, Event::Refract);
            // Snell's law at each face, from the drawn directions and the normals.
            EXPECT_NEAR(s.n_from * std::sin(s.incidence_deg * kDegree),
                        s.n_to * std::sin(s.leaving_deg * kDegree), 1e-9);
        }
        EXPECT_DOUBLE_EQ(r.steps[0].n_from, 1.0);
        EXPECT_DOUBLE_EQ(r.steps[0].n_to, 1.5);
        EXPECT_DOUBLE_EQ(r.steps[1].n_to, 1.0);
        // The beam is aimed to four decimals: within 0.01° of the textbook's angles.
        EXPECT_NEAR(r.steps[0].incidence_deg, incidence, 0.01);
        EXPECT_NEAR(r.steps[0].leaving_deg, 30, 0.01);
        EXPECT_NEAR(r.steps[1].incidence_deg, 30, 0.01);
        EXPECT_NEAR(r.steps[1].leaving_deg, incidence, 0.01);
        EXPECT_NEAR(r.total_deviation_deg, deviation, 0.01);
        EXPECT_NEAR(r.steps[0].deviation_deg + r.steps[1].deviation_deg, r.total_deviation_deg,
                    1e-9);
        EXPECT_EQ(r.end, "absorbed at screen");
        const std::string text = format_section_ray_report(r);
        EXPECT_NE(text.find("1. prism: refracted, incidence 48.59°, refraction 30.00°"),
                  std::string::npos)
            << text;
        EXPECT_NE(text.find("37.18°"), std::string::npos) << text;
        ++checked;
    }
    EXPECT_EQ(checked, 12);  // the beam light's fan across its width
}

}  // namespace
}  // namespace lenslab
