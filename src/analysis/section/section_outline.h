#pragma once
// The cross-section of one scene object by a section plane, as curves in plane coordinates.
// Closed solids give closed loops; flat open surfaces (triangles, discs, rectangles) and
// meshes give the segments where they cut the plane.
//
// A lens cut through its axis is exact: its two face profiles from the sag formula, joined
// by the rim. Any other solid (a sphere, a tilted lens, an implicit formula, which need not
// be convex) is contoured by marching squares over its inside test on a grid across its
// bounding sphere, each crossing bisected onto the surface: the points lie on the surface
// to ~1e-9 of a grid cell, though features thinner than a cell can be missed.

#include <vector>

#include "analysis/section/section_plane.h"
#include "scene/scene.h"

namespace lenslab {

struct SectionCurve {
    std::vector<DiagramPoint> points;
    bool closed = false;
};

struct SectionOutlineOptions {
    int grid = 96;  // marching-squares cells across a solid's section
};

std::vector<SectionCurve> section_outline(const Shape& shape, const SectionPlane& plane,
                                          const SectionOutlineOptions& options = {});

}  // namespace lenslab
