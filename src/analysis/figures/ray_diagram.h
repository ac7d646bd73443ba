#pragma once
// A ray diagram of a coaxial lens system, as plain geometry: the meridional cross-section of
// every lens (its true surface profiles), the optical axis, a fan of real rays in the F, d
// and C lines from the left to past the focus, the focal points and principal planes, a
// scale bar and a title. The SVG writer (ray_diagram_svg.h) and the editor's dock both draw
// this one model, so the two pictures cannot disagree.
//
// Coordinates are the system's (z along the axis, y up across it), in the scene's unit;
// stroke widths, dash lengths, text sizes and text offsets are in pixels.

#include <string>
#include <vector>

#include "analysis/report/lens_report.h"
#include "analysis/system/optical_system.h"

namespace lenslab {

struct DiagramColour {
    int r = 0, g = 0, b = 0;
};

// Rays in the colours of their Fraunhofer lines (F, d, C), as optics texts draw them.
inline constexpr DiagramColour kDiagramBlueF{30, 90, 230};
inline constexpr DiagramColour kDiagramYellowGreenD{150, 170, 0};
inline constexpr DiagramColour kDiagramRedC{220, 30, 30};
// Glass drawn in section: its fill and outline (the ray diagram and the section view alike).
inline constexpr DiagramColour kDiagramGlassFill{170, 205, 235};
inline constexpr DiagramColour kDiagramGlassEdge{40, 80, 130};

struct DiagramPoint {
    double z = 0, y = 0;
};

struct DiagramPath {
    std::vector<DiagramPoint> points;
    DiagramColour stroke;
    double stroke_opacity = 1.0;
    double width = 1.0;
    double dash = 0.0;  // dash length; 0: solid
    bool closed = false;
    bool filled = false;
    DiagramColour fill;
    double fill_opacity = 1.0;
};

struct DiagramText {
    DiagramPoint at;
    std::string text;
    DiagramColour colour;
    double size = 13.0;
    double dx = 0.0, dy = 0.0;  // offset from `at` in pixels (+dy: down the picture)
    enum class Anchor { Start, Middle, End } anchor = Anchor::Middle;
};

// A fixed-size dot (focal points).
struct DiagramDot {
    DiagramPoint at;
    DiagramColour colour;
    double radius = 4.0;
};

struct LegendEntry {
    DiagramColour colour;
    std::string text;
};

struct RayDiagram {
    double z_min = 0, z_max = 1, y_min = -1, y_max = 1;  // what must be in view
    std::vector<DiagramPath> paths;  // in drawing order: lenses, axis, rays, marks
    std::vector<DiagramDot> dots;
    std::vector<DiagramText> labels;
    std::vector<LegendEntry> legend;
    std::string title;
    std::string subtitle;         // what the rays are, under the title
    double scale_bar = 10.0;      // length of the scale bar, in the scene's unit; 0: none
    std::string scale_bar_label;  // "10 mm"
};

struct RayDiagramOptions {
    int rays_per_fan = 9;  // meridional rays across the aperture, per wavelength
    // The scene's length unit, for the labels ("mm"); empty: a scene file declares none, so
    // lengths are labelled "units" rather than a unit the scene may not use.
    std::string unit;
};

// The diagram of `system`; `report` gives the paraxial points and the beam's aperture.
RayDiagram make_ray_diagram(const OpticalSystem& system, const LensReport& report,
                            const RayDiagramOptions& options = {});

// 1, 2 or 5 times a power of ten, at most `target` (and near it): a scale bar's length.
double diagram_round_length(double target);

// The uniform scale (pixels per unit) and offset that fit a diagram into a picture of
// width x height pixels, keeping `margin` pixels free on the sides and `top` / `bottom`
// above and below (for the title and the scale bar). Lens shapes keep their true aspect.
struct DiagramView {
    double scale = 1, left = 0, top = 0;  // pixel of (z_min, y_max)
    double z_min = 0, y_max = 0;
    double x(double z) const { return left + (z - z_min) * scale; }
    double y(double y_) const { return top + (y_max - y_) * scale; }
};
DiagramView fit_diagram(const RayDiagram& d, double width, double height, double margin, double top,
                        double bottom);

}  // namespace lenslab
