#include "analysis/figures/plot_panel.h"

#include <cmath>
#include <cstdio>

#include "analysis/section/section_view.h"
#include "util/format_number.h"

namespace lenslab {

namespace {

DiagramPath plot_line(DiagramPoint a, DiagramPoint b) {
    DiagramPath p;
    p.points = {a, b};
    p.stroke = kPlotGrey;
    p.width = 0.7;
    return p;
}

}  // namespace

DiagramPath plot_box(double z0, double y0, double z1, double y1, DiagramColour colour) {
    DiagramPath p;
    p.points = {{z0, y0}, {z1, y0}, {z1, y1}, {z0, y1}};
    p.closed = true;
    p.stroke = colour;
    return p;
}

DiagramText plot_label(DiagramPoint at, const std::string& text, double dy,
                       DiagramText::Anchor anchor) {
    DiagramText t;
    t.at = at;
    t.text = text;
    t.colour = kPlotInk;
    t.size = 12;
    t.dy = dy;
    t.anchor = anchor;
    return t;
}

std::string plot_length(double v, const std::string& unit) {
    return printf_text("%.4g ", v) + (unit.empty() ? "units" : unit);
}

std::vector<LegendEntry> wavelength_legend(const std::vector<double>& wavelengths) {
    std::vector<LegendEntry> legend;
    for (double nm : wavelengths) {
        legend.push_back({wavelength_colour(nm), printf_text("%.1f nm", nm)});
    }
    return legend;
}

void frame_panels(RayDiagram& d, int panels) {
    // A hair wider than the panels, so the frame's clip keeps their outer edges.
    d.z_min = -1.02;
    d.z_max = 1.02 + (panels - 1) * (2 + kPlotPanelGap);
    d.y_min = -1.25;
    d.y_max = 1.2;
    d.scale_bar = 0;
}

void draw_plot_panel(RayDiagram& d, const PlotPanel& p) {
    const double cz = p.centre.z, cy = p.centre.y;
    const auto to_z = [&](double x) { return cz - 1 + 2 * (x - p.x_min) / (p.x_max - p.x_min); };
    const auto to_y = [&](double y) { return cy - 1 + 2 * (y - p.y_min) / (p.y_max - p.y_min); };
    d.paths.push_back(plot_box(cz - 1, cy - 1, cz + 1, cy + 1, kPlotGrey));
    if (p.x_min < 0 && p.x_max > 0)
        d.paths.push_back(plot_line({to_z(0), cy - 1}, {to_z(0), cy + 1}));
    if (p.y_min < 0 && p.y_max > 0)
        d.paths.push_back(plot_line({cz - 1, to_y(0)}, {cz + 1, to_y(0)}));
    for (const PlotCurve& c : p.curves) {
        DiagramPath path;
        path.stroke = c.colour;
        path.width = 1.6;
        path.dash = c.dash;
        for (size_t i = 0; i <= c.x.size(); ++i) {
            if (i < c.x.size() && !std::isnan(c.x[i]) && !std::isnan(c.y[i])) {
                path.points.push_back({to_z(c.x[i]), to_y(c.y[i])});
            } else if (!path.points.empty()) {
                d.paths.push_back(path);
                path.points.clear();
            }
        }
    }
    d.labels.push_back(plot_label({cz, cy + 1}, p.title, -6));
    d.labels.push_back(plot_label({cz - 1, cy - 1}, p.x_min_label, 14, DiagramText::Anchor::Start));
    d.labels.push_back(plot_label({cz + 1, cy - 1}, p.x_max_label, 14, DiagramText::Anchor::End));
    DiagramText corner =
        plot_label({cz - 1, cy + 1}, p.y_max_label, 14, DiagramText::Anchor::Start);
    corner.dx = 4;
    d.labels.push_back(corner);
}

}  // namespace lenslab
