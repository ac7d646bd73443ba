// The ray diagram drawn as an image (ray_diagram_image.h), the PNG twin of the SVG: the same
// picture size, a white ground, dots and filled shapes in their colours where the layout
// puts them, and nothing of a path outside the diagram's frame.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <regex>
#include <string>

#include "analysis/figures/ray_diagram_image.h"
#include "analysis/figures/ray_diagram_svg.h"

namespace lenslab {
namespace {

std::array<int, 3> pixel_at(const Image8& image, double x, double y) {
    const size_t i = (size_t(y) * size_t(image.width) + size_t(x)) * 3;
    return {image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]};
}

TEST(RayDiagramImage, SameLayoutAsTheSvg) {
    RayDiagram d;
    d.z_min = 0;
    d.z_max = 10;
    d.y_min = -5;
    d.y_max = 5;
    d.scale_bar = 0;
    DiagramPath square;
    square.points = {{1, 1}, {3, 1}, {3, 3}, {1, 3}};
    square.closed = square.filled = true;
    square.fill = {0, 0, 200};
    square.stroke = {0, 0, 200};
    d.paths.push_back(square);
    DiagramPath outside;  // runs off the frame to the right: clipped there
    outside.points = {{9, -4}, {30, -4}};
    outside.stroke = {200, 0, 0};
    outside.width = 3;
    d.paths.push_back(outside);
    d.dots.push_back({{7, 0}, {0, 150, 0}, 5});

    const Image8 image = ray_diagram_image(d, 400, 100);
    const std::string svg = ray_diagram_svg(d, 400, 100);
    std::smatch m;
    ASSERT_TRUE(std::regex_search(svg, m, std::regex("width=\"([0-9.]+)\" height=\"([0-9.]+)\"")));
    EXPECT_EQ(image.width, std::lround(std::stod(m[1])));
    EXPECT_EQ(image.height, std::lround(std::stod(m[2])));
    // Where the SVG puts the dot and the square's centre (fit_diagram with the writer's
    // margins: 24 at the sides, 64 above, 56 below).
    const DiagramView v = fit_diagram(d, image.width, image.height, 24, 64, 56);
    EXPECT_EQ(pixel_at(image, v.x(7), v.y(0)), (std::array<int, 3>{0, 150, 0}));
    EXPECT_EQ(pixel_at(image, v.x(2), v.y(2)), (std::array<int, 3>{0, 0, 200}));
    EXPECT_EQ(pixel_at(image, v.x(5), v.y(2)), (std::array<int, 3>{255, 255, 255}));
    EXPECT_EQ(pixel_at(image, v.x(9.5), v.y(-4)), (std::array<int, 3>{200, 0, 0}));
    EXPECT_EQ(pixel_at(image, v.x(10) + 10, v.y(-4)), (std::array<int, 3>{255, 255, 255}));
}

}  // namespace
}  // namespace lenslab
