#include "analysis/figures/curve_figures.h"

#include <algorithm>
#include <cmath>

#include "analysis/figures/plot_panel.h"
#include "analysis/section/section_view.h"

namespace lenslab {

namespace {

constexpr double kSagittalDash = 6;

// The largest |v| over the values, or 1 when there is none (a flat chart).
double curve_half_range(const std::vector<double>& values) {
    double largest = 0;
    for (double v : values) {
        if (!std::isnan(v)) largest = std::max(largest, std::abs(v));
    }
    return largest > 0 ? 1.05 * largest : 1.0;
}

}  // namespace

RayDiagram field_curves_figure(const FieldCurves& r, const std::string& unit,
                               const std::string& field_unit) {
    RayDiagram d;
    frame_panels(d, 2);
    std::vector<double> foci, distortion, wavelengths;
    double max_field = 0;
    for (const FieldCurve& c : r.curves) {
        wavelengths.push_back(c.wavelength_nm);
        for (const FieldCurvePoint& p : c.points) {
            foci.insert(foci.end(), {p.tangential, p.sagittal});
            distortion.push_back(100.0 * p.distortion);
            max_field = std::max(max_field, p.field);
        }
    }
    const double focus_range = curve_half_range(foci),
                 distortion_range = curve_half_range(distortion);
    PlotPanel focus, distort;
    focus.centre = {0, 0};
    distort.centre = {2 + kPlotPanelGap, 0};
    for (PlotPanel* p : {&focus, &distort}) {
        p->y_min = 0;
        p->y_max = max_field > 0 ? max_field : 1;
        p->y_max_label = "field " + printf_text("%g ", max_field) + field_unit;
    }
    focus.x_min = -focus_range;
    focus.x_max = focus_range;
    focus.title = "foci: tangential solid, sagittal dashed";
    focus.x_min_label = plot_length(-focus_range, unit);
    focus.x_max_label = plot_length(focus_range, unit);
    distort.x_min = -distortion_range;
    distort.x_max = distortion_range;
    distort.title = "distortion";
    distort.x_min_label = printf_text("%.3g %%", -distortion_range);
    distort.x_max_label = printf_text("%.3g %%", distortion_range);
    for (const FieldCurve& c : r.curves) {
        PlotCurve tangential, sagittal, real;
        for (const FieldCurvePoint& p : c.points) {
            tangential.x.push_back(p.tangential);
            sagittal.x.push_back(p.sagittal);
            // On the axis distortion is 0/0: the curve starts there at 0.
            real.x.push_back(p.field == 0 ? 0.0 : 100.0 * p.distortion);
            for (PlotCurve* curve : {&tangential, &sagittal, &real}) curve->y.push_back(p.field);
        }
        for (PlotCurve* curve : {&tangential, &sagittal, &real}) {
            curve->colour = wavelength_colour(c.wavelength_nm);
        }
        sagittal.dash = kSagittalDash;
        focus.curves.push_back(std::move(tangential));
        focus.curves.push_back(std::move(sagittal));
        distort.curves.push_back(std::move(real));
    }
    draw_plot_panel(d, focus);
    draw_plot_panel(d, distort);
    d.legend = wavelength_legend(wavelengths);
    d.title = "Field curves, image plane " + printf_text("%.4f", r.image_z) + " (system z)";
    d.subtitle = "foci from the image plane along z, > 0 behind it";
    return d;
}

RayDiagram focal_shift_figure(const FocalShift& s, const std::string& unit) {
    RayDiagram d;
    frame_panels(d, 1);
    const double range = curve_half_range(s.shift);
    PlotPanel p;
    p.x_min = s.wavelengths.front();
    p.x_max = s.wavelengths.back();
    p.y_min = -range;
    p.y_max = range;
    p.title = "shift against wavelength";
    p.x_min_label = printf_text("%g nm", p.x_min);
    p.x_max_label = printf_text("%g nm", p.x_max);
    p.y_max_label = "+";
    p.y_max_label += plot_length(range, unit);
    p.curves.push_back({s.wavelengths, s.shift, kPlotInk, 0});
    draw_plot_panel(d, p);
    d.title = "Chromatic focal shift";
    d.subtitle = "paraxial image position minus that at " + printf_text("%.2f nm", s.reference_nm);
    return d;
}

namespace {

// One field's MTF in an MTF figure: tangential solid, sagittal dashed, in one colour.
struct MtfFigureCurves {
    DiagramColour colour;
    std::string label;
    const std::vector<double>& tangential;
    const std::vector<double>& sagittal;
};

RayDiagram mtf_panel_figure(const std::vector<double>& frequencies,
                            const std::vector<double>& diffraction_limit,
                            const std::vector<MtfFigureCurves>& fields, std::string title,
                            const std::string& unit,
                            const char* limit_label = "diffraction limit") {
    RayDiagram figure;
    PlotPanel panel;
    panel.x_min = 0;
    panel.x_max = frequencies.empty() ? 1.0 : frequencies.back();
    panel.y_min = 0;
    panel.y_max = 1;
    panel.title = std::move(title);
    panel.x_min_label = printf_text("%g", 0.0);
    panel.x_max_label =
        printf_text("%.4g", panel.x_max) + " cycles/" + (unit.empty() ? "unit" : unit);
    panel.y_max_label = printf_text("%g", 1.0);
    // Every MTF is 1 at frequency 0 (normalised): the curves start there.
    const auto from_zero = [](std::vector<double> v, double at_zero) {
        v.insert(v.begin(), at_zero);
        return v;
    };
    const bool has_zero = !frequencies.empty() && frequencies.front() == 0.0;
    const auto curve = [&](const std::vector<double>& values, DiagramColour colour, double dash) {
        if (has_zero) return PlotCurve{frequencies, values, colour, dash};
        return PlotCurve{from_zero(frequencies, 0.0), from_zero(values, 1.0), colour, dash};
    };
    panel.curves = {curve(diffraction_limit, kPlotGrey, 0)};
    figure.legend = {{kPlotGrey, limit_label}};
    for (const MtfFigureCurves& f : fields) {
        if (f.tangential.empty()) continue;  // a field that could not be measured
        panel.curves.push_back(curve(f.tangential, f.colour, 0));
        panel.curves.push_back(curve(f.sagittal, f.colour, 6));
        figure.legend.push_back({f.colour, f.label});
    }
    // One panel of ±1 about the origin, as the bench's other charts lay theirs out.
    figure.z_min = -1.02;
    figure.z_max = 1.02;
    figure.y_min = -1.25;
    figure.y_max = 1.15;
    draw_plot_panel(figure, panel);
    figure.title = "MTF";
    figure.scale_bar = 0;
    return figure;
}

}  // namespace

RayDiagram mtf_figure(const DiffractionFigures& d, const std::string& unit) {
    return mtf_panel_figure(
        d.mtf.frequencies, d.mtf.diffraction_limit,
        {{kDiagramBlueF, "T solid, S dashed", d.mtf.tangential, d.mtf.sagittal}},
        "MTF on axis, " + printf_text("%.1f nm", d.wavelength_nm) + ", Strehl " +
            printf_text("%.3f", d.strehl),
        unit);
}

RayDiagram field_mtf_figure(const FieldMtfs& m, const std::string& unit,
                            const std::string& field_unit) {
    const DiagramColour colours[] = {kDiagramBlueF, kDiagramYellowGreenD, kDiagramRedC, kPlotInk};
    std::vector<MtfFigureCurves> fields;
    for (size_t k = 0; k < m.fields.size(); ++k) {
        const FieldMtf& f = m.fields[k];
        fields.push_back({colours[k % std::size(colours)], printf_text("%g ", f.field) + field_unit,
                          f.tangential, f.sagittal});
    }
    // Short legend entries: one per field must fit the figure's width.
    return mtf_panel_figure(m.frequencies, m.diffraction_limit, fields,
                            "polychromatic; tangential solid, sagittal dashed", unit, "limit");
}

}  // namespace lenslab
