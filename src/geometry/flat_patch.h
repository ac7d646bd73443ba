#pragma once
// Where a flat shape lies and what it covers in its own plane: what a detector grids, what the
// section view cuts and what the detector's size check measures, asked of a shape
// (Shape::flat_patch) instead of cast to each flat type.

#include <vector>

#include "geometry/plane_frame.h"

namespace lenslab {

struct FlatPatch {
    PlaneFrame frame;
    // The extent in the frame's (u, v): [u0, u1] x [v0, v1], the patch's bounding box.
    double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
    // A disc of this radius about the frame's origin; 0 for a polygon.
    double radius = 0;
    // A polygon's corners in order (a triangle's three, a rectangle's four); none for a disc.
    std::vector<Vec3> corners;

    bool is_disc() const { return radius > 0; }
};

}  // namespace lenslab
