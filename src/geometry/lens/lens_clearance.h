#pragma once
// The air space between two neighbouring lens elements: the back face of one and the front
// face of the next, both in the same local frame (the group's axis and x_axis). Checking
// each element alone misses two elements that are apart on the axis but overlap at the rim.

#include "geometry/lens/lens_surface.h"

namespace lenslab {

struct Clearance {
    double gap;    // smallest axial distance from the back face to the front face
    DiscPoint at;  // where it is smallest
};

// The smallest of spacing + front.sag_xy(x, y) - back.sag_xy(x, y) over the disc of radius
// `semi_diameter`, where `spacing` is the distance from the back face's vertex to the front
// face's vertex. Samples the disc densely (the rim included), then refines the worst sample
// along its radius to rounding; a dip much narrower than the sample spacing can still be
// missed. Points where a sag is not a finite number are skipped (each element refuses those
// on its own).
Clearance smallest_clearance(const LensSurface& back, const LensSurface& front, double spacing,
                             double semi_diameter);

}  // namespace lenslab
