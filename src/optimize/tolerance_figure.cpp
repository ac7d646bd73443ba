#include "optimize/tolerance_figure.h"

#include <algorithm>
#include <cmath>

#include "analysis/figures/plot_panel.h"

namespace lenslab {

namespace {

// Bins of the histogram: about √N, 10 to 40.
int bin_count(size_t trials) {
    return std::clamp(int(std::lround(std::sqrt(double(trials)))), 10, 40);
}

constexpr DiagramColour kNominalColour{200, 60, 40};

// A vertical dashed line at x over the panel's height.
PlotCurve nominal_line(double x, double y_min, double y_max) {
    return {{x, x}, {y_min, y_max}, kNominalColour, 5};
}

}  // namespace

RayDiagram tolerance_figure(const ToleranceReport& report, const std::string& unit) {
    const MonteCarloSummary& m = report.monte_carlo;
    RayDiagram d;
    frame_panels(d, 2);
    std::vector<double> sorted = m.criteria;
    std::sort(sorted.begin(), sorted.end());
    const double low = std::min(report.nominal, sorted.empty() ? report.nominal : sorted.front());
    const double high = std::max(report.nominal, sorted.empty() ? report.nominal : sorted.back());
    const double margin = high > low ? 0.02 * (high - low) : 0.01 * std::max(high, 1e-12);
    const double x_min = low - margin, x_max = high + margin;

    // The histogram as a step line over the bins.
    const int bins = bin_count(sorted.size());
    std::vector<int> counts(size_t(bins), 0);
    for (double c : sorted) {
        const int b = int((c - x_min) / (x_max - x_min) * bins);
        ++counts[size_t(std::clamp(b, 0, bins - 1))];
    }
    const int most = std::max(1, *std::max_element(counts.begin(), counts.end()));
    PlotCurve steps{{}, {}, kPlotInk, 0};
    for (int b = 0; b < bins; ++b) {
        const double x0 = x_min + (x_max - x_min) * b / bins;
        const double x1 = x_min + (x_max - x_min) * (b + 1) / bins;
        for (double x : {x0, x1}) {
            steps.x.push_back(x);
            steps.y.push_back(counts[size_t(b)]);
        }
    }
    PlotPanel histogram;
    histogram.centre = {0, 0};
    histogram.x_min = x_min;
    histogram.x_max = x_max;
    histogram.y_min = 0;
    histogram.y_max = 1.05 * most;
    histogram.title = "made lenses per bin";
    histogram.y_max_label = printf_text("%d", most);
    histogram.curves = {steps, nominal_line(report.nominal, 0, histogram.y_max)};

    // The cumulative yield: the share of lenses at or below each criterion (at or above an
    // MTF: the curve climbs from the right).
    const bool up = report.higher_is_better;
    if (up) std::reverse(sorted.begin(), sorted.end());
    // An MTF has no unit.
    const auto label = [&](double v) { return up ? printf_text("%.4g", v) : plot_length(v, unit); };
    PlotCurve share{{up ? x_max : x_min}, {0}, kPlotInk, 0};
    for (size_t i = 0; i < sorted.size(); ++i) {
        share.x.push_back(sorted[i]);
        share.y.push_back(double(i) / double(m.trials));
        share.x.push_back(sorted[i]);
        share.y.push_back(double(i + 1) / double(m.trials));
    }
    share.x.push_back(up ? x_min : x_max);
    share.y.push_back(double(sorted.size()) / double(std::max(1, m.trials)));
    PlotPanel yield;
    yield.centre = {2 + kPlotPanelGap, 0};
    yield.x_min = x_min;
    yield.x_max = x_max;
    yield.y_min = 0;
    yield.y_max = 1;
    yield.title = up ? "share of lenses at or above" : "share of lenses at or below";
    yield.y_max_label = "100%";
    yield.curves = {share, nominal_line(report.nominal, 0, 1)};
    for (PlotPanel* p : {&histogram, &yield}) {
        p->x_min_label = label(x_min);
        p->x_max_label = label(x_max);
        draw_plot_panel(d, *p);
    }
    d.title = "Monte Carlo of " + printf_text("%d", m.trials) + " made lenses" +
              (m.failed > 0 ? printf_text(" (%d could not be evaluated)", m.failed) : "");
    d.subtitle = std::string(up ? "polychromatic MTF over the fields"
                             : report.criterion == "rms_wavefront" ? "polychromatic RMS wavefront "
                                                                     "over the fields"
                                                                   : "polychromatic RMS spot over "
                                                                     "the fields") +
                 std::string(report.compensated ? ", each refocused" : "") +
                 "; dashed: the nominal design, " + label(report.nominal);
    return d;
}

}  // namespace lenslab
