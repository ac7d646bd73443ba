// The bench's chart panels (plot_panel.h): the data range maps onto the panel's ±1 square
// about its centre, and a missing value (a vignetted ray) breaks a curve in two.

#include <gtest/gtest.h>

#include <cmath>

#include "analysis/figures/plot_panel.h"

namespace lenslab {
namespace {

TEST(PlotPanel, MapsTheRangeAndBreaksCurvesAtMissingValues) {
    PlotPanel p;
    p.centre = {10, -5};
    p.x_min = 400;
    p.x_max = 700;
    p.y_min = -0.5;
    p.y_max = 1.5;
    p.curves.push_back({{400, 550, 600, 700}, {-0.5, 0.5, NAN, 1.5}, kPlotInk, 0});
    RayDiagram d;
    draw_plot_panel(d, p);
    std::vector<const DiagramPath*> curves;
    for (const DiagramPath& path : d.paths) {
        if (path.width > 1) curves.push_back(&path);
    }
    ASSERT_EQ(curves.size(), 2u);
    ASSERT_EQ(curves[0]->points.size(), 2u);
    EXPECT_DOUBLE_EQ(curves[0]->points[0].z, 9.0);   // x_min at the left edge
    EXPECT_DOUBLE_EQ(curves[0]->points[0].y, -6.0);  // y_min at the bottom
    EXPECT_DOUBLE_EQ(curves[0]->points[1].z, 10.0);  // 550 nm: halfway
    EXPECT_DOUBLE_EQ(curves[0]->points[1].y, -5.0);
    ASSERT_EQ(curves[1]->points.size(), 1u);
    EXPECT_DOUBLE_EQ(curves[1]->points[0].z, 11.0);
    EXPECT_DOUBLE_EQ(curves[1]->points[0].y, -4.0);
}

}  // namespace
}  // namespace lenslab
