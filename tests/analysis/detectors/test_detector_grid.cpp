// A detector's cells and the area each has on the surface: what turns power into
// irradiance. Checked against the surfaces' areas (pi r^2, a triangle's half cross
// product) and exact overlaps.

#include <gtest/gtest.h>

#include <cmath>

#include "analysis/detectors/detector_grid.h"
#include "math/constants.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

const SceneObject& only_object(const Scene& s) { return s.objects.at(0); }

Scene scene_with(const std::string& object) {
    return parse_scene(R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]}, "objects": [)" +
                       object + "]}");
}

TEST(DetectorGrid, DiscCellsAddUpToPiRSquared) {
    const Scene s =
        scene_with(R"({"type": "disc", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 2,
        "material": {"color": 0.5}, "detector": {"resolution": 37}})");
    const DetectorGrid g = DetectorGrid::for_object(only_object(s));
    EXPECT_EQ(g.cells_u(), 37);
    EXPECT_EQ(g.cells_v(), 37);
    EXPECT_NEAR(g.surface_area(), kPi * 4, 1e-6 * kPi * 4);
    // The centre cell is wholly inside, a corner cell wholly outside.
    EXPECT_NEAR(g.cell_area(g.cell_at(0, 0)), g.cell_width() * g.cell_height(), 1e-15);
    EXPECT_EQ(g.cell_area(0), 0.0);
}

TEST(DetectorGrid, DiscOverlapOfAQuarterAndAHalf) {
    // The square [0, r]^2 holds a quarter of the disc; [-r, r] x [0, r] half of it.
    EXPECT_NEAR(rectangle_disc_overlap(0, 1, 0, 1, 1), kPi / 4, 1e-6);
    EXPECT_NEAR(rectangle_disc_overlap(-1, 1, 0, 1, 1), kPi / 2, 1e-6);
    EXPECT_NEAR(rectangle_disc_overlap(-3, 3, -3, 3, 1), kPi, 1e-6);
    EXPECT_EQ(rectangle_disc_overlap(0.8, 1, 0.8, 1, 1), 0.0);  // corner beyond the rim
}

TEST(DetectorGrid, TriangleCellsAddUpToItsArea) {
    // Area = |e1 x e2| / 2 = |(3, 0, 0) x (1, 2, 0)| / 2 = 3.
    const Scene s =
        scene_with(R"({"type": "triangle", "vertices": [[0, 0, 0], [3, 0, 0], [1, 2, 0]],
        "material": {"color": 0.5}, "detector": {"resolution": [30, 20]}})");
    const DetectorGrid g = DetectorGrid::for_object(only_object(s));
    EXPECT_NEAR(g.surface_area(), 3.0, 1e-12);
    EXPECT_NEAR(g.u_max() - g.u_min(), 3.0, 1e-12);  // u along the first edge
    EXPECT_NEAR(g.v_max() - g.v_min(), 2.0, 1e-12);
    EXPECT_NEAR(rectangle_triangle_overlap(0, 1, 0, 1, {{0, 0}, {2, 0}, {0, 2}}), 1.0, 1e-15);
    EXPECT_NEAR(rectangle_triangle_overlap(1, 2, 1, 2, {{0, 0}, {2, 0}, {0, 2}}), 0.0, 1e-15);
    EXPECT_NEAR(rectangle_triangle_overlap(0, 2, 0, 1, {{0, 0}, {2, 0}, {0, 2}}), 1.5, 1e-15);
}

TEST(DetectorGrid, RectangleCellsAreSquareAlongTheLongerSide) {
    const Scene s = scene_with(
        R"({"type": "rectangle", "center": [0, 0, 0], "normal": [0, 0, 1], "size": [4, 2],
        "material": {"color": 0.5}, "detector": {"resolution": 64}})");
    const DetectorGrid g = DetectorGrid::for_object(only_object(s));
    EXPECT_EQ(g.cells_u(), 64);
    EXPECT_EQ(g.cells_v(), 32);
    EXPECT_NEAR(g.surface_area(), 8.0, 1e-12);
    EXPECT_DOUBLE_EQ(g.cell_width(), g.cell_height());
    // Cells count from the lowest v, row by row.
    EXPECT_EQ(g.cell_at(-1.99, -0.99), 0);
    EXPECT_EQ(g.cell_at(1.99, -0.99), 63);
    EXPECT_EQ(g.cell_at(-1.99, 0.99), 64 * 31);
    EXPECT_NEAR(g.cell_u(0), -2 + 2.0 / 64, 1e-15);
}

TEST(DetectorGrid, RefusesAnObjectThatIsNotADetector) {
    const Scene s =
        scene_with(R"({"type": "disc", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 2,
        "material": {"color": 0.5}})");
    EXPECT_THROW(DetectorGrid::for_object(only_object(s)), std::invalid_argument);
}

}  // namespace
}  // namespace lenslab
