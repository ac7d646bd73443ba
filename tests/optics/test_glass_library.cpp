// Finding glasses by name across the built-in materials and the makers' catalogues.

#include <gtest/gtest.h>

#include "optics/glass_library.h"

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

}  // namespace
}  // namespace lenslab
