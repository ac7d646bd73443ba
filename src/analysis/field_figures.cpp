#include "analysis/field_figures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analysis/section_view.h"

namespace lenslab {

namespace {

constexpr DiagramColour kFigureInk{30, 30, 30};
constexpr DiagramColour kFigureGrey{150, 150, 150};
constexpr double kPanelGap = 0.3;  // between panels, in panel sizes
constexpr double kPanelPixels = 320;

std::string figure_text(const char* format, double v) {
    char text[64];
    std::snprintf(text, sizeof text, format, v);
    return text;
}

std::string figure_length(double v, const std::string& unit) {
    return figure_text("%.4g ", v) + (unit.empty() ? "units" : unit);
}

std::string field_label(double field, const std::string& field_unit) {
    return "field " + figure_text("%g ", field) + field_unit;
}

DiagramPath figure_box(double z0, double y0, double z1, double y1, DiagramColour colour) {
    DiagramPath p;
    p.points = {{z0, y0}, {z1, y0}, {z1, y1}, {z0, y1}};
    p.closed = true;
    p.stroke = colour;
    return p;
}

DiagramPath figure_line(DiagramPoint a, DiagramPoint b, DiagramColour colour) {
    DiagramPath p;
    p.points = {a, b};
    p.stroke = colour;
    p.width = 0.7;
    return p;
}

DiagramText figure_label(DiagramPoint at, const std::string& text, double dy,
                         DiagramText::Anchor anchor = DiagramText::Anchor::Middle) {
    DiagramText t;
    t.at = at;
    t.text = text;
    t.colour = kFigureInk;
    t.size = 12;
    t.dy = dy;
    t.anchor = anchor;
    return t;
}

std::vector<LegendEntry> wavelength_legend(const std::vector<double>& wavelengths) {
    std::vector<LegendEntry> legend;
    for (double nm : wavelengths)
        legend.push_back({wavelength_colour(nm), figure_text("%.1f nm", nm)});
    return legend;
}

// The largest distance of a field's hits, all wavelengths, from its polychromatic centroid.
double spot_extent(const FieldSpots& f) {
    double extent = 0;
    for (const WavelengthSpot& s : f.spots) {
        for (const Vec3& q : s.spot.points) {
            extent = std::max(extent, std::hypot(q.x - f.polychromatic.centroid_x,
                                                 q.y - f.polychromatic.centroid_y));
        }
    }
    return extent;
}

}  // namespace

double field_figure_width(int panels) {
    return 48 + kPanelPixels * (panels + kPanelGap * (panels - 1)) + 40;
}

RayDiagram spot_diagram_figure(const SpotDiagrams& spots, const std::string& unit,
                               const std::string& field_unit) {
    RayDiagram d;
    // One scale for every panel: the largest spot (or Airy circle) about its centre.
    double half = 0;
    for (const FieldSpots& f : spots.fields) half = std::max({half, f.airy_radius, spot_extent(f)});
    half = half > 0 ? 1.1 * half : 1.0;
    const double side = 2 * half, step = side * (1 + kPanelGap);
    const int panels = static_cast<int>(spots.fields.size());
    d.z_min = -half;
    d.z_max = -half + step * (panels - 1) + side;
    d.y_min = -half - 0.3 * side;
    d.y_max = half + 0.12 * side;
    for (int i = 0; i < panels; ++i) {
        const FieldSpots& f = spots.fields[i];
        const double cz = i * step;  // the panel's centre; the field's centroid maps there
        d.paths.push_back(figure_box(cz - half, -half, cz + half, half, kFigureGrey));
        DiagramPath airy;
        for (int k = 0; k < 72; ++k) {
            const double a = 2 * M_PI * k / 72;
            airy.points.push_back({cz + f.airy_radius * std::cos(a), f.airy_radius * std::sin(a)});
        }
        airy.closed = true;
        airy.stroke = kFigureInk;
        d.paths.push_back(airy);
        for (const WavelengthSpot& s : f.spots) {
            for (const Vec3& q : s.spot.points) {
                d.dots.push_back(
                    {{cz + q.x - f.polychromatic.centroid_x, q.y - f.polychromatic.centroid_y},
                     wavelength_colour(s.wavelength_nm),
                     1.5});
            }
        }
        d.labels.push_back(figure_label({cz, half}, field_label(f.field, field_unit), -8));
        d.labels.push_back(figure_label(
            {cz, -half}, "RMS " + figure_length(f.polychromatic.rms_radius, unit), 18));
        d.labels.push_back(
            figure_label({cz, -half}, "GEO " + figure_length(spot_extent(f), unit), 34));
        d.labels.push_back(figure_label({cz, -half},
                                        figure_text("centroid y %.5g", f.polychromatic.centroid_y) +
                                            (unit.empty() ? "" : " " + unit),
                                        50));
    }
    d.legend = wavelength_legend(spots.wavelengths);
    d.title = "Spot diagrams, image plane " + figure_text("%.4f", spots.image_z) +
              " (system z); hexapolar " + figure_text("%g", spots.rings) + " rings, " +
              figure_text("%g", spots.rays_per_beam) + " rays a beam";
    d.subtitle = "about each field's polychromatic centroid; circle: Airy radius " +
                 figure_length(spots.fields.empty() ? 0 : spots.fields[0].airy_radius, unit);
    d.scale_bar = diagram_round_length(0.5 * half);
    d.scale_bar_label = figure_length(d.scale_bar, unit);
    return d;
}

RayDiagram ray_fan_figure(const RayFans& fans, const std::string& unit,
                          const std::string& field_unit) {
    RayDiagram d;
    double largest = 0;
    for (const FieldFans& f : fans.fields) {
        for (const RayFan& fan : f.fans) {
            for (const std::vector<double>* v : {&fan.tangential, &fan.sagittal}) {
                for (double e : *v) {
                    if (!std::isnan(e)) largest = std::max(largest, std::abs(e));
                }
            }
        }
    }
    const double scale = largest > 0 ? largest : 1.0;  // ε = ±scale at the panel's edges
    const std::string full_scale = figure_text("+%.4g ", scale) + (unit.empty() ? "units" : unit);
    const double step = 2 * (1 + kPanelGap);
    const int rows = static_cast<int>(fans.fields.size());
    d.z_min = -1;
    d.z_max = -1 + step + 2;
    d.y_max = 1 + 0.15;
    d.y_min = 1 - step * (rows - 1) - 2 - 0.25;
    for (int row = 0; row < rows; ++row) {
        const FieldFans& f = fans.fields[row];
        const double cy = -row * step;
        for (int col = 0; col < 2; ++col) {
            const double cz = col * step;
            d.paths.push_back(figure_box(cz - 1, cy - 1, cz + 1, cy + 1, kFigureGrey));
            d.paths.push_back(figure_line({cz - 1, cy}, {cz + 1, cy}, kFigureGrey));
            d.paths.push_back(figure_line({cz, cy - 1}, {cz, cy + 1}, kFigureGrey));
            for (const RayFan& fan : f.fans) {
                const std::vector<double>& e = col == 0 ? fan.tangential : fan.sagittal;
                DiagramPath curve;
                curve.stroke = wavelength_colour(fan.wavelength_nm);
                curve.width = 1.6;
                // A vignetted ray breaks the curve.
                for (size_t i = 0; i <= e.size(); ++i) {
                    if (i < e.size() && !std::isnan(e[i])) {
                        curve.points.push_back({cz + fans.pupil[i], cy + e[i] / scale});
                    } else if (!curve.points.empty()) {
                        d.paths.push_back(curve);
                        curve.points.clear();
                    }
                }
            }
            d.labels.push_back(
                figure_label({cz, cy + 1},
                             field_label(f.field, field_unit) +
                                 (col == 0 ? ": tangential e_y (py)" : ": sagittal e_x (px)"),
                             -6));
            d.labels.push_back(
                figure_label({cz - 1, cy + 1}, full_scale, 12, DiagramText::Anchor::Start));
            d.labels.push_back(figure_label({cz + 1, cy}, col == 0 ? "py = 1" : "px = 1", 14,
                                            DiagramText::Anchor::End));
        }
    }
    d.legend = wavelength_legend([&] {
        std::vector<double> nm;
        if (!fans.fields.empty()) {
            for (const RayFan& fan : fans.fields[0].fans) nm.push_back(fan.wavelength_nm);
        }
        return nm;
    }());
    d.title = "Ray fans, image plane " + figure_text("%.4f", fans.image_z) + " (system z)";
    // Short: the legend shares its line. The full scale is in every panel's corner.
    d.subtitle = "error from the chief ray at " + figure_text("%.2f nm", fans.primary_nm);
    d.scale_bar = 0;
    return d;
}

}  // namespace lenslab
