// The field map (analysis/aberrations/field_map.h): RMS spot over x-y fields. For a rotationally
// symmetric lens a field in x is one in y turned by 90 degrees: the chief ray lands at the
// same height along x, and the map is mirror-symmetric; on the y axis each cell is the spot
// diagram's RMS at that field.

#include <gtest/gtest.h>

#include <cmath>

#include "../lens_scene_builder.h"
#include "analysis/aberrations/field_map.h"
#include "analysis/aberrations/spot_diagrams.h"
#include "analysis/system/field_beam.h"
#include "analysis/system/paraxial.h"

namespace lenslab {
namespace {

using test::glass;
using test::lens_scene;
using test::sphere;

OpticalSystem singlet() {
    return build_optical_system(
        lens_scene({{"singlet", 0, 6, 30, sphere(60), sphere(-200), glass("N-BK7")}}));
}

FirstOrder first_order_of(const OpticalSystem& system, double max_field) {
    FirstOrderOptions o;
    o.epd = 20;
    o.fields = {0, max_field};
    return first_order(system, paraxial_trace(system, kLineD), o);
}

TEST(FieldMap, AFieldInXIsOneInYTurned) {
    const OpticalSystem system = singlet();
    const FirstOrder f = first_order_of(system, 4);
    const double z = system.last_vertex() + f.image_position;
    const FieldBeam in_y = trace_field_beam(system, f, 4.0, kLineD, 6);
    const FieldBeam in_x = trace_field_beam(system, f, 0.0, kLineD, 6, 4.0);
    ASSERT_TRUE(in_y.chief && in_x.chief);
    const Vec3 cy = at_plane(in_y.chief->point, in_y.chief->direction, z);
    const Vec3 cx = at_plane(in_x.chief->point, in_x.chief->direction, z);
    EXPECT_NEAR(cx.x, cy.y, 1e-9 * std::abs(cy.y));
    EXPECT_NEAR(cx.y, 0.0, 1e-12);
    EXPECT_NEAR(cy.x, 0.0, 1e-12);
}

TEST(FieldMap, TheMapIsSymmetricAndItsYAxisIsTheSpotDiagrams) {
    const OpticalSystem system = singlet();
    const FirstOrder f = first_order_of(system, 4);
    FieldMapOptions o;
    o.points = 5;
    o.max_field = 4;
    o.wavelength_nm = kLineD;
    o.image_z = system.last_vertex() + f.image_position;
    const FieldMap map = field_map(system, f, o);
    ASSERT_EQ(map.rms.size(), 5u);
    EXPECT_EQ(map.fields_x, (std::vector<double>{-4, -2, 0, 2, 4}));
    for (size_t j = 0; j < 5; ++j)
        for (size_t i = 0; i < 5; ++i) {
            EXPECT_NEAR(map.rms[j][i], map.rms[j][4 - i], 1e-9 * map.rms[j][i]);
            EXPECT_NEAR(map.rms[j][i], map.rms[4 - j][i], 1e-9 * map.rms[j][i]);
        }
    // The hexapolar grid is six-fold, not four-fold: x and y fields agree to its sampling.
    EXPECT_NEAR(map.rms[2][4], map.rms[4][2], 0.01 * map.rms[4][2]);
    SpotOptions spots;
    spots.fields = {2, 4};
    spots.wavelengths = {kLineD};
    spots.image_z = o.image_z;
    const SpotDiagrams d = spot_diagrams(system, f, spots);
    EXPECT_NEAR(map.rms[3][2], d.fields[0].spots[0].spot.rms_radius, 1e-12);
    EXPECT_NEAR(map.rms[4][2], d.fields[1].spots[0].spot.rms_radius, 1e-12);
}

}  // namespace
}  // namespace lenslab
