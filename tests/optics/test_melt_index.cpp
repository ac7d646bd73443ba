// A melt of a catalogue glass: its n_d and V_d moved by exactly the departures asked, its
// dispersion's shape kept (the relative partial dispersion P_g,F unchanged, since the melt
// scales n(λ) - n_d by one factor).

#include <gtest/gtest.h>

#include "optics/glass.h"
#include "optics/melt_index.h"

namespace lenslab {
namespace {

TEST(MeltIndex, MovesNdAndVdByTheDeparturesAndKeepsThePartialDispersion) {
    const Glass* bk7 = find_glass("N-BK7");
    ASSERT_NE(bk7, nullptr);
    // SCHOTT's data sheet: n_d 1.51680, V_d 64.17; a melt sheet's step 1 departure.
    const IndexModelPtr melt = melt_index(bk7->model, 0.0004, -0.3);
    EXPECT_NEAR(melt->n_d(), bk7->model->n_d() + 0.0004, 1e-12);
    EXPECT_NEAR(melt->abbe_number(), bk7->model->abbe_number() - 0.3, 1e-9);
    EXPECT_NEAR(bk7->model->n_d(), 1.51680, 5e-6);
    const double g = 435.8343;  // the g line (Hg)
    const auto p_gf = [g](const IndexModel& m) {
        return (m.n(g) - m.n(kLineF)) / (m.n(kLineF) - m.n(kLineC));
    };
    EXPECT_NEAR(p_gf(*melt), p_gf(*bk7->model), 1e-12);
}

TEST(MeltIndex, NoDepartureIsTheCatalogueGlassItself) {
    const Glass* f2 = find_glass("F2");
    ASSERT_NE(f2, nullptr);
    EXPECT_EQ(melt_index(f2->model, 0, 0), f2->model);
}

}  // namespace
}  // namespace lenslab
