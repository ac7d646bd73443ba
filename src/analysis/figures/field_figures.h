#pragma once
// The spot diagrams and ray fans of `lenslab analyze` drawn as pictures, in the ray
// diagram's model (ray_diagram.h), so ray_diagram_svg writes them as SVG:
// - spot diagrams: one square panel per field, all at one scale, each centred on its
//   field's polychromatic centroid, the hits coloured by wavelength, the Airy circle
//   (1.22 λ N_w at the primary wavelength) drawn black about that centroid, a scale bar;
// - ray fans: per field (top to bottom) the tangential fan ε_y against py and the
//   sagittal fan ε_x against px, one curve per wavelength, every panel at one vertical scale
//   (±max |ε|, written beside it).

#include <string>

#include "analysis/aberrations/ray_fans.h"
#include "analysis/aberrations/spot_diagrams.h"
#include "analysis/figures/ray_diagram.h"

namespace lenslab {

// `unit` names the system's length unit in the labels ("mm"; empty: "units"); `field_unit`
// is "deg" for field angles or the length unit for object heights.
RayDiagram spot_diagram_figure(const SpotDiagrams& spots, const std::string& unit,
                               const std::string& field_unit);
RayDiagram ray_fan_figure(const RayFans& fans, const std::string& unit,
                          const std::string& field_unit,
                          FanQuantity quantity = FanQuantity::TransverseError);

// The SVG picture's width in pixels for a figure of `panels` panels side by side.
double field_figure_width(int panels);

}  // namespace lenslab
