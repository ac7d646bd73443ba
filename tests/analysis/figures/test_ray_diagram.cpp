// The ray diagram: lens outlines on the true surfaces, rays that really cross at the focus,
// the focal points and principal planes where the paraxial trace puts them; and its SVG.

#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include "../lens_scene_builder.h"
#include "analysis/figures/ray_diagram.h"
#include "analysis/figures/ray_diagram_svg.h"

namespace lenslab {
namespace {

using test::lens_scene;
using test::LensSpec;
using test::sphere;

// The hyperbolic plano-convex lens of the equation-lens issue: a perfect focus at 100.
const LensSpec kHyperbolic{"hyperbolic",
                           0,
                           5,
                           25,
                           sphere(0),
                           R"({"shape": "conic", "radius": -50, "k": -2.25})",
                           R"({"transparency": 1, "ior": 1.5})"};

TEST(RayDiagram, RaysMeetAtTheFocusOfAPerfectLens) {
    const OpticalSystem system = build_optical_system(lens_scene({kHyperbolic}));
    const LensReport report = analyze_lens_system(system, {});
    RayDiagramOptions in_mm;
    in_mm.unit = "mm";
    const RayDiagram d = make_ray_diagram(system, report, in_mm);
    int outlines = 0, rays = 0;
    for (const DiagramPath& p : d.paths) {
        if (p.closed) {
            ++outlines;
            // Every outline point lies on one of the lens's two surfaces.
            for (const DiagramPoint& q : p.points) {
                const double r = std::abs(q.y);
                const double on = std::min(std::abs(q.z - system.surfaces[0].z_at(r)),
                                           std::abs(q.z - system.surfaces[1].z_at(r)));
                EXPECT_LT(on, 1e-12);
            }
            continue;
        }
        // Rays: they run from the left edge to the right edge; a ray of the d line (the
        // lens is a constant-index glass: all lines coincide) crosses the axis at F'.
        if (p.points.size() < 4) continue;
        ++rays;
        EXPECT_DOUBLE_EQ(p.points.front().z, d.z_min);
        EXPECT_NEAR(p.points.back().z, d.z_max, 1e-9);
        const DiagramPoint a = p.points[p.points.size() - 2], b = p.points.back();
        if (std::abs(a.y) < 1e-9) continue;  // the axial ray
        const double z_cross = a.z - a.y * (b.z - a.z) / (b.y - a.y);
        EXPECT_NEAR(z_cross, report.paraxial.z_rear_focus, 1e-6);
    }
    EXPECT_EQ(outlines, 1);
    EXPECT_EQ(rays, 27);  // 9 rays in each of 3 lines
    ASSERT_EQ(d.dots.size(), 2u);
    EXPECT_DOUBLE_EQ(d.dots[1].at.z, report.paraxial.z_rear_focus);
    std::string names;
    for (const DiagramText& t : d.labels) names += t.text + ";";
    EXPECT_EQ(names, "n = 1.5;H;H';F;F';");
    EXPECT_NE(d.title.find("EFL 100.00 mm, BFL 100.00 mm at 587.56 nm (d line)"), std::string::npos)
        << d.title;
}

TEST(RayDiagram, LabelsClaimNoUnitTheSceneDoesNotDeclare) {
    // A scene file has no length unit: without one given, the title and the scale bar say
    // "units" (the editor's diagram of a unitless scene said "mm").
    const LensSpec lens{"LA1509", 0, 3.6, 25.4, sphere(51.5), sphere(0), test::glass("N-BK7")};
    const OpticalSystem system = build_optical_system(lens_scene({lens}));
    const RayDiagram d = make_ray_diagram(system, analyze_lens_system(system, {}));
    EXPECT_EQ(d.title.find("mm"), std::string::npos) << d.title;
    EXPECT_NE(d.title.find(" units, BFL "), std::string::npos) << d.title;
    EXPECT_TRUE(d.scale_bar_label.ends_with(" units")) << d.scale_bar_label;
}

TEST(RayDiagram, DivergingLensShowsItsVirtualFocus) {
    // Thorlabs LC1120 (plano-concave, f = -100): the rays spread, and dashed lines trace
    // them back to the virtual focus in front of the lens.
    const LensSpec lens{"LC1120", 0, 4.0, 25.4, sphere(-51.46), sphere(0), test::glass("N-BK7")};
    const OpticalSystem system = build_optical_system(lens_scene({lens}));
    const LensReport report = analyze_lens_system(system, {});
    ASSERT_LT(report.paraxial.efl, 0);
    const RayDiagram d = make_ray_diagram(system, report);
    int dashed_back = 0;
    for (const DiagramPath& p : d.paths) {
        if (p.dash > 0 && p.points.size() == 2 && p.points[1].z < 0) {
            ++dashed_back;
            EXPECT_NEAR(p.points[1].z, report.paraxial.z_rear_focus, 1e-9);
        }
    }
    EXPECT_EQ(dashed_back, 9);
    EXPECT_LT(d.z_min, report.paraxial.z_rear_focus);
}

TEST(RayDiagram, SvgIsAStandalonePicture) {
    const LensSpec crown{"crown", 0, 4, 25.4, sphere(62.8), sphere(-45.7), test::glass("N-BK7")};
    const LensSpec flint{"flint", 4, 2.5, 25.4, sphere(-45.7), sphere(-128.2), test::glass("SF5")};
    const OpticalSystem system = build_optical_system(lens_scene({crown, flint}));
    RayDiagramOptions in_mm;
    in_mm.unit = "mm";
    const std::string svg =
        ray_diagram_svg(make_ray_diagram(system, analyze_lens_system(system, {}), in_mm));
    EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
    EXPECT_EQ(svg.substr(svg.size() - 7), "</svg>\n");
    const auto count = [&](const std::string& what) {
        const std::regex re(what);
        return std::distance(std::sregex_iterator(svg.begin(), svg.end(), re),
                             std::sregex_iterator());
    };
    EXPECT_EQ(count("<polygon "), 2);    // two lenses
    EXPECT_GE(count("<polyline "), 27);  // rays, axis, planes
    EXPECT_EQ(count("<circle "), 2);     // F and F'
    EXPECT_EQ(count(">N-BK7<"), 1);
    EXPECT_EQ(count(">SF5<"), 1);
    EXPECT_EQ(count(">20 mm<"), 1);  // the scale bar
    EXPECT_EQ(count("\\bnan\\b|\\binf\\b"), 0);
}

}  // namespace
}  // namespace lenslab
