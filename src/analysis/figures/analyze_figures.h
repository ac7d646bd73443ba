#pragma once
// The figures `lenslab analyze` writes to files (--svg, --spots-svg, --fans-svg, --curves-svg,
// --focal-shift-svg, --mtf-svg), drawn from measured results: for those files, and as SVG
// text for callers that want the picture rather than a file (the Python module's
// Analysis.figure).

#include <string>
#include <vector>

#include "analysis/figures/ray_diagram.h"
#include "analysis/report/analyze_request.h"

namespace lenslab {

// The figures' names: "ray_diagram", "spots", "fans", "field_curves", "focal_shift", "mtf".
const std::vector<std::string>& bench_figure_names();

// A figure and the size it is drawn at (its width and least height, in pixels).
struct BenchFigure {
    RayDiagram diagram;
    double width = 0, min_height = 0;
};

// The figure `name` of `results` (measured for `request`, whose unit labels it). Throws
// AnalyzeRequestError for an unknown name or a figure whose table the request did not ask
// for (spots without --spots, ...).
BenchFigure bench_figure(const AnalyzeResults& results, const AnalyzeRequest& request,
                         const std::string& name);

// Writes a figure as SVG, or as PNG when the file's name ends in ".png"; atomically either
// way, so a failed write leaves no half file and says why it failed.
void write_bench_figure(const std::string& file, const BenchFigure& figure);

// The same as the SVG text `lenslab analyze` writes for it.
std::string bench_figure_svg(const AnalyzeResults& results, const AnalyzeRequest& request,
                             const std::string& name);

}  // namespace lenslab
