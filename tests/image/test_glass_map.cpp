// The glass map: one mark per glass of the filter, where n_d and V_d put it (V_d decreasing to
// the right, as catalogues print the chart), coloured by maker.

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <regex>
#include <string>

#include "image/glass_map.h"
#include "optics/glass_library.h"
#include "optics/glass_search.h"

namespace lenslab {
namespace {

struct GlassMapMark {
    double x, y;
};

// Every <circle class="glass"> of the SVG by "MAKER:NAME".
std::map<std::string, GlassMapMark> glass_marks(const std::string& svg) {
    std::map<std::string, GlassMapMark> marks;
    const std::regex circle(
        "<circle class=\"glass\" cx=\"([-0-9.]+)\" cy=\"([-0-9.]+)\" r=\"3\" fill=\"#[0-9a-f]{6}\" "
        "data-name=\"([^\"]+)\" data-maker=\"([^\"]+)\"");
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), circle);
         it != std::sregex_iterator(); ++it) {
        const std::smatch& m = *it;
        marks[m[4].str() + ":" + m[3].str()] = {std::stod(m[1].str()), std::stod(m[2].str())};
    }
    return marks;
}

TEST(GlassMap, OneMarkPerGlassWhereNdAndVdPutIt) {
    GlassQuery q;
    q.maker = "SCHOTT";
    q.n_d = ValueRange{1.5, 1.65};
    const std::vector<const Glass*> found = search_glasses(q);
    ASSERT_GT(found.size(), 10u);
    const std::string svg = glass_map_svg(found);
    const auto marks = glass_marks(svg);
    EXPECT_EQ(marks.size(), glasses_on_map(found).size());
    EXPECT_EQ(glasses_on_map(found).size(), found.size());  // SCHOTT prints n_d, V_d for all
    // The frame holds every glass, and the marks sit at the linear map of (V_d, n_d).
    const GlassMapFrame f = glass_map_frame(glasses_on_map(found));
    for (const Glass* g : found) {
        const auto it = marks.find("SCHOTT:" + g->name);
        ASSERT_NE(it, marks.end()) << g->name;
        const double x =
            f.left + (f.v_max - glass_v_d(*g)) / (f.v_max - f.v_min) * (f.right - f.left);
        const double y =
            f.top + (f.n_max - glass_n_d(*g)) / (f.n_max - f.n_min) * (f.bottom - f.top);
        EXPECT_NEAR(it->second.x, x, 1e-3) << g->name;
        EXPECT_NEAR(it->second.y, y, 1e-3) << g->name;
        EXPECT_GT(x, f.left);
        EXPECT_LT(x, f.right);
        EXPECT_GT(y, f.top);
        EXPECT_LT(y, f.bottom);
    }
    // As catalogues draw it: the crown N-BK7 (V_d 64.17) left of the flint F2 (36.37) and
    // below it (n_d 1.5168 against 1.6200).
    const GlassMapMark bk7 = marks.at("SCHOTT:N-BK7"), f2 = marks.at("SCHOTT:F2");
    EXPECT_LT(bk7.x, f2.x);
    EXPECT_GT(bk7.y, f2.y);
    EXPECT_NE(svg.find(">N-BK7</text>"), std::string::npos);  // a well-known glass is labelled
}

TEST(GlassMap, TheImageHasTheMarksInTheirColours) {
    GlassQuery q;
    q.maker = "OHARA";
    q.n_d = ValueRange{1.51, 1.52};
    const std::vector<const Glass*> found = search_glasses(q);
    ASSERT_FALSE(found.empty());
    const Image8 img = glass_map_image(found);
    const GlassMapFrame f = glass_map_frame(glasses_on_map(found));
    ASSERT_EQ(img.width, f.width);
    for (const Glass* g : found) {
        const long x = std::lround(f.x(glass_v_d(*g))), y = std::lround(f.y(glass_n_d(*g)));
        const unsigned char* p = &img.rgb[(size_t(y) * size_t(img.width) + size_t(x)) * 3];
        EXPECT_FALSE(p[0] == 255 && p[1] == 255 && p[2] == 255) << g->name << ": no mark";
    }
}

}  // namespace
}  // namespace lenslab
