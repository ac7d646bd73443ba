#include "analysis/figures/field_figures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analysis/figures/plot_panel.h"
#include "analysis/section/section_view.h"

namespace lenslab {

namespace {

constexpr double kPanelGap = 0.3;  // between panels, in panel sizes
constexpr double kPanelPixels = 320;

std::string field_label(double field, const std::string& field_unit) {
    return "field " + printf_text("%g ", field) + field_unit;
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
    // A hair wider than the panels, so the frame's clip keeps their outer edges.
    d.z_min = -half - 0.01 * side;
    d.z_max = -half + step * (panels - 1) + 1.01 * side;
    d.y_min = -half - 0.3 * side;
    d.y_max = half + 0.12 * side;
    for (int i = 0; i < panels; ++i) {
        const FieldSpots& f = spots.fields[i];
        const double cz = i * step;  // the panel's centre; the field's centroid maps there
        d.paths.push_back(plot_box(cz - half, -half, cz + half, half, kPlotGrey));
        DiagramPath airy;
        for (int k = 0; k < 72; ++k) {
            const double a = 2 * M_PI * k / 72;
            airy.points.push_back({cz + f.airy_radius * std::cos(a), f.airy_radius * std::sin(a)});
        }
        airy.closed = true;
        airy.stroke = kPlotInk;
        d.paths.push_back(airy);
        for (const WavelengthSpot& s : f.spots) {
            for (const Vec3& q : s.spot.points) {
                d.dots.push_back(
                    {{cz + q.x - f.polychromatic.centroid_x, q.y - f.polychromatic.centroid_y},
                     wavelength_colour(s.wavelength_nm),
                     1.5});
            }
        }
        d.labels.push_back(plot_label({cz, half}, field_label(f.field, field_unit), -8));
        d.labels.push_back(
            plot_label({cz, -half}, "RMS " + plot_length(f.polychromatic.rms_radius, unit), 18));
        d.labels.push_back(plot_label({cz, -half}, "GEO " + plot_length(spot_extent(f), unit), 34));
        // On the axis the centroid is 0 up to rounding: print 0, not 1e-15.
        const double y = f.polychromatic.centroid_y;
        d.labels.push_back(
            plot_label({cz, -half},
                       "centroid y " + plot_length(std::abs(y) < 1e-9 * half ? 0.0 : y, unit), 50));
    }
    d.legend = wavelength_legend(spots.wavelengths);
    d.title = "Spot diagrams, image plane " + printf_text("%.4f", spots.image_z) +
              " (system z); hexapolar " + printf_text("%d", spots.rings) + " rings, " +
              printf_text("%d", spots.rays_per_beam) + " rays a beam";
    d.subtitle = "about each field's polychromatic centroid; circle: Airy radius " +
                 plot_length(spots.fields.empty() ? 0 : spots.fields[0].airy_radius, unit);
    d.scale_bar = diagram_round_length(0.5 * half);
    d.scale_bar_label = plot_length(d.scale_bar, unit);
    return d;
}

RayDiagram ray_fan_figure(const RayFans& fans, const std::string& unit,
                          const std::string& field_unit, FanQuantity quantity) {
    const bool opd = quantity == FanQuantity::Opd;
    RayDiagram d;
    std::vector<double> errors;
    for (const FieldFans& f : fans.fields) {
        for (const RayFan& fan : f.fans) {
            errors.insert(errors.end(), fan.tangential.begin(), fan.tangential.end());
            errors.insert(errors.end(), fan.sagittal.begin(), fan.sagittal.end());
        }
    }
    double scale = 0;  // ε = ±scale at the panels' edges
    for (double e : errors) {
        if (!std::isnan(e)) scale = std::max(scale, std::abs(e));
    }
    if (!(scale > 0)) scale = 1.0;
    const double step = 2 * (1 + kPanelGap);
    const int rows = static_cast<int>(fans.fields.size());
    d.z_min = -1.02;
    d.z_max = -1 + step + 2.02;
    d.y_max = 1 + 0.15;
    d.y_min = 1 - step * (rows - 1) - 2 - 0.25;
    for (int row = 0; row < rows; ++row) {
        const FieldFans& f = fans.fields[row];
        for (int col = 0; col < 2; ++col) {
            PlotPanel p;
            p.centre = {col * step, -row * step};
            p.y_min = -scale;
            p.y_max = scale;
            p.title = field_label(f.field, field_unit) +
                      (opd ? (col == 0 ? ": tangential W (py)" : ": sagittal W (px)")
                           : (col == 0 ? ": tangential e_y (py)" : ": sagittal e_x (px)"));
            p.x_min_label = col == 0 ? "py = -1" : "px = -1";
            p.x_max_label = col == 0 ? "py = 1" : "px = 1";
            p.y_max_label =
                "+" + (opd ? printf_text("%.4g waves", scale) : plot_length(scale, unit));
            for (const RayFan& fan : f.fans) {
                // A vignetted ray (NaN) breaks the curve.
                p.curves.push_back({fans.pupil, col == 0 ? fan.tangential : fan.sagittal,
                                    wavelength_colour(fan.wavelength_nm), 0});
            }
            draw_plot_panel(d, p);
        }
    }
    std::vector<double> wavelengths;
    if (!fans.fields.empty()) {
        for (const RayFan& fan : fans.fields[0].fans) wavelengths.push_back(fan.wavelength_nm);
    }
    d.legend = wavelength_legend(wavelengths);
    d.title = std::string(opd ? "OPD fans" : "Ray fans") + ", image plane " +
              printf_text("%.4f", fans.image_z) + " (system z)";
    // Short: the legend shares its line. The full scale is in every panel's corner.
    d.subtitle = opd ? std::string("waves, against each wavelength's chief ray")
                     : "error from the chief ray at " + printf_text("%.2f nm", fans.primary_nm);
    d.scale_bar = 0;
    return d;
}

}  // namespace lenslab
