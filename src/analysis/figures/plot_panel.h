#pragma once
// Charts drawn in the ray diagram's model (ray_diagram.h), so ray_diagram_svg writes them: a
// square panel with its frame, zero lines, curves in data coordinates and labels, and the
// small pieces the bench's figures share (frames, labels, a legend of wavelengths).

#include <string>
#include <vector>

#include "analysis/figures/ray_diagram.h"
#include "util/format_number.h"

namespace lenslab {

inline constexpr DiagramColour kPlotInk{30, 30, 30};
inline constexpr DiagramColour kPlotGrey{150, 150, 150};

struct PlotCurve {
    std::vector<double> x, y;  // data; a NaN in either breaks the curve
    DiagramColour colour;
    double dash = 0;  // dash length in pixels; 0: solid
};

// The panel spans ±1 diagram units about `centre`; the data range maps onto it.
struct PlotPanel {
    DiagramPoint centre;
    double x_min = -1, x_max = 1, y_min = -1, y_max = 1;
    std::string title;                     // above the panel
    std::string x_min_label, x_max_label;  // under the ends of the x axis
    std::string y_max_label;               // inside the top-left corner
    std::vector<PlotCurve> curves;
};

void draw_plot_panel(RayDiagram& diagram, const PlotPanel& panel);

inline constexpr double kPlotPanelGap = 0.6;  // between panels side by side, in diagram units
// The frame of `panels` panels side by side, the first centred on the origin, the next
// 2 + kPlotPanelGap along: room above for titles, below for axis labels; no scale bar.
void frame_panels(RayDiagram& diagram, int panels);

DiagramPath plot_box(double z0, double y0, double z1, double y1, DiagramColour colour);
// A label at `at`, moved `dy` pixels down the picture.
DiagramText plot_label(DiagramPoint at, const std::string& text, double dy,
                       DiagramText::Anchor anchor = DiagramText::Anchor::Middle);
// "0.0125 mm", or "units" when the scene's unit is not known.
std::string plot_length(double v, const std::string& unit);
std::vector<LegendEntry> wavelength_legend(const std::vector<double>& wavelengths);

}  // namespace lenslab
