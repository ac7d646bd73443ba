#pragma once
// A 2-D section view of a scene: every object's cross-section by a plane, and rays traced
// in that plane through all objects (section_outline.h, section_rays.h), drawn as a
// RayDiagram so the editor and the SVG writer (ray_diagram_svg.h) show the same picture.

#include <optional>
#include <vector>

#include "analysis/figures/ray_diagram.h"
#include "analysis/section/section_outline.h"
#include "analysis/section/section_plane.h"
#include "analysis/section/section_rays.h"

namespace lenslab {

struct SectionObject {
    int object = -1;  // index into Scene::objects
    std::vector<SectionCurve> curves;
};

// A rectangle of the plane, in plane coordinates.
struct SectionExtent {
    double a_min = -1, a_max = 1, b_min = -1, b_max = 1;
};

struct SectionView {
    SectionPlane plane;
    std::vector<SectionObject> objects;  // those the plane cuts, in scene order
    std::vector<SectionRayPath> rays;
    SectionExtent extent;  // what the picture shows; first every cross-section and ray start
};

struct SectionViewOptions {
    SectionOutlineOptions outline;
    SectionRayOptions rays;  // its escape_length is raised to the picture's diagonal
};

SectionView make_section_view(const Scene& scene, const SectionPlane& plane,
                              const SectionViewOptions& options = {});

// The box of `object`'s cross-section in the plane; nothing when the plane misses it.
std::optional<SectionExtent> section_bounds(const SectionView& view, int object);

// The extent worth showing for `object`: its cross-section with room of `room` times its
// size on every side, so it and the rays near it are drawn large; all of `view` for an
// object the plane misses (or -1).
SectionExtent focus_extent(const SectionView& view, int object, double room = 1.0);

// The drawing: cross-sections filled by material (glass, mirror, lamp, opaque), the
// `selected` object's outlined in orange, rays in their true colours (a laser's line, white
// light's F, d and C lines where glass disperses) and faded by weight.
RayDiagram section_diagram(const Scene& scene, const SectionView& view, int selected = -1);

// A colour of a wavelength: the ray diagram's for the F, d and C lines, else its CIE 1931
// colour in sRGB, darkened to show on white.
DiagramColour wavelength_colour(double nm);

}  // namespace lenslab
