// Finding glasses by name across the built-in materials and the makers' catalogues, and
// searching them by maker, n_d and V_d.

#include <gtest/gtest.h>

#include <cmath>

#include "optics/glass_library.h"
#include "optics/glass_search.h"

namespace lenslab {
namespace {

TEST(GlassLibrary, CatalogueNamesIgnoreCase) {
    const Glass* g = find_glass("n-lak22");
    ASSERT_NE(g, nullptr);
    EXPECT_EQ(g->name, "N-LAK22");
    EXPECT_EQ(g->maker, "SCHOTT");
    for (const char* name : {"N-SF10", "N-SF6HT", "S-BSL7", "H-K9L", "L-BAL35", "s-tih6"})
        EXPECT_NE(find_glass(name), nullptr) << name;
}

TEST(GlassLibrary, BuiltInNamesComeFirst) {
    // Scenes written before the catalogues keep their numbers: "N-BK7" is the built-in one.
    const Glass* bk7 = find_glass("N-BK7");
    ASSERT_NE(bk7, nullptr);
    EXPECT_TRUE(bk7->maker.empty());
    EXPECT_EQ(bk7, &glass_catalogue()[0]);
    EXPECT_NE(find_glass("water"), nullptr);
}

TEST(GlassLibrary, MakerPrefixChoosesBetweenMakers) {
    // SF10 is both SCHOTT's lead flint and HIKARI's: the bare name is refused with the choices.
    const GlassLookup bare = lookup_glass("SF10");
    EXPECT_EQ(bare.glass, nullptr);
    EXPECT_EQ(bare.error,
              "glass 'SF10' is in several catalogues; name one of SCHOTT:SF10, HIKARI:SF10");
    const Glass* schott = find_glass("schott:sf10");
    const Glass* hikari = find_glass("HIKARI:SF10");
    ASSERT_NE(schott, nullptr);
    ASSERT_NE(hikari, nullptr);
    EXPECT_EQ(schott->maker, "SCHOTT");
    EXPECT_EQ(hikari->maker, "HIKARI");
    EXPECT_NE(schott->model->n_d(), hikari->model->n_d());  // two melts, two formulas
}

TEST(GlassLibrary, UnknownNamesAreRefusedWithTheClosestMatches) {
    EXPECT_EQ(lookup_glass("NBK7").error, "unknown glass 'NBK7'; did you mean N-BK7 (SCHOTT)?");
    EXPECT_EQ(lookup_glass("N-LAK222").error,
              "unknown glass 'N-LAK222'; did you mean N-LAK22 (SCHOTT)?");
    EXPECT_EQ(lookup_glass("watr").error, "unknown glass 'watr'; did you mean water?");
    EXPECT_EQ(lookup_glass("unobtainium").error,
              "unknown glass 'unobtainium' (see `lenslab glass`)");
    EXPECT_EQ(lookup_glass("SHOTT:N-BK7").error,
              "unknown glass maker 'SHOTT' in 'SHOTT:N-BK7' (makers: SCHOTT, OHARA, CDGM, HOYA, "
              "HIKARI, SUMITA)");
    EXPECT_EQ(lookup_glass("OHARA:N-BK7").error,
              "unknown glass 'OHARA:N-BK7'; did you mean N-BK7 (SCHOTT)?");
    EXPECT_EQ(find_glass("unobtainium"), nullptr);
}

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
