// Searching the glasses by maker, n_d and V_d (`lenslab glass --maker --nd --vd`).

#include <gtest/gtest.h>

#include "optics/glass_library.h"
#include "optics/glass_search.h"

namespace lenslab {
namespace {

TEST(GlassSearch, RangesParseAndRefuse) {
    const auto r = parse_value_range("1.5:1.6");
    ASSERT_TRUE(r);
    EXPECT_TRUE(r->contains(1.55));
    EXPECT_FALSE(r->contains(1.61));
    ASSERT_TRUE(parse_value_range("50:"));
    EXPECT_TRUE(parse_value_range("50:")->contains(90));
    EXPECT_TRUE(parse_value_range(":1.6")->contains(1.0));
    for (const char* bad : {"1.5", "1.6:1.5", "a:b", "1.5:1.6:1.7", "nan:1", "1.5x:1.6"})
        EXPECT_FALSE(parse_value_range(bad)) << bad;
}

TEST(GlassSearch, FindsEveryGlassInTheBoxAndNoOther) {
    GlassQuery q;
    q.maker = "schott";
    q.n_d = parse_value_range("1.5:1.52");
    q.v_d = parse_value_range("60:70");
    const auto found = search_glasses(q);
    bool has_bk7 = false;
    for (const Glass* g : found) {
        EXPECT_EQ(g->maker, "SCHOTT");
        EXPECT_TRUE(q.n_d->contains(glass_n_d(*g)) && q.v_d->contains(glass_v_d(*g))) << g->name;
        has_bk7 = has_bk7 || g->name == "N-BK7";
    }
    EXPECT_TRUE(has_bk7);
    // Against a plain count over the same data: nothing in the box is left out.
    size_t expected = 0;
    for (const Glass& g : maker_glasses()) {
        if (g.maker == "SCHOTT" && q.n_d->contains(glass_n_d(g)) && q.v_d->contains(glass_v_d(g)))
            ++expected;
    }
    EXPECT_EQ(found.size(), expected);
    GlassQuery builtin;
    builtin.maker = "builtin";
    EXPECT_EQ(search_glasses(builtin).size(), glass_catalogue().size());
}

}  // namespace
}  // namespace lenslab
