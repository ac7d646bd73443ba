#include "analysis/figures/analyze_figures.h"

#include "analysis/figures/curve_figures.h"
#include "analysis/figures/field_figures.h"
#include "analysis/figures/ray_diagram_image.h"
#include "analysis/figures/ray_diagram_svg.h"
#include "image/image_io.h"
#include "util/atomic_file.h"

namespace lenslab {

namespace {

// The field figures' size: field_figure_width(panels) wide and at least 300 high.
BenchFigure field_figure(RayDiagram diagram, int panels) {
    return {std::move(diagram), field_figure_width(panels), 300};
}

[[noreturn]] void not_asked(const std::string& name, const std::string& option) {
    throw AnalyzeRequestError("figure '" + name + "': it needs --" + option +
                              ", which was not asked for");
}

}  // namespace

const std::vector<std::string>& bench_figure_names() {
    static const std::vector<std::string> names{"ray_diagram", "spots", "fans",    "field_curves",
                                                "focal_shift", "mtf",   "opd_fans"};
    return names;
}

BenchFigure bench_figure(const AnalyzeResults& r, const AnalyzeRequest& request,
                         const std::string& name) {
    const std::string& unit = request.unit;
    const std::string field_unit =
        request.object_distance > 0 ? (unit.empty() ? "units" : unit) : "deg";
    if (name == "ray_diagram") {
        RayDiagramOptions diagram;
        diagram.unit = unit;
        return {make_ray_diagram(r.system, r.report, diagram), 1200, 360};
    }
    if (name == "spots") {
        if (!r.spots) not_asked(name, "spots");
        return field_figure(spot_diagram_figure(*r.spots, unit, field_unit),
                            static_cast<int>(r.spots->fields.size()));
    }
    if (name == "fans") {
        if (!r.fans) not_asked(name, "fans");
        return field_figure(ray_fan_figure(*r.fans, unit, field_unit), 2);
    }
    if (name == "opd_fans") {
        if (!r.opd_fans) not_asked(name, "opd-fans");
        return field_figure(ray_fan_figure(*r.opd_fans, unit, field_unit, FanQuantity::Opd), 2);
    }
    if (name == "field_curves") {
        if (!r.curves) not_asked(name, "field-curves");
        return field_figure(field_curves_figure(*r.curves, unit, field_unit), 2);
    }
    if (name == "focal_shift") {
        if (!r.shift) not_asked(name, "focal-shift");
        return field_figure(focal_shift_figure(*r.shift, unit), 1);
    }
    if (name == "mtf") {
        if (!r.diffraction || !request.mtf) not_asked(name, "mtf");
        if (r.field_mtf) return field_figure(field_mtf_figure(*r.field_mtf, unit, field_unit), 1);
        return field_figure(mtf_figure(*r.diffraction, unit), 1);
    }
    std::string known;
    for (const std::string& n : bench_figure_names()) known += (known.empty() ? "" : ", ") + n;
    throw AnalyzeRequestError("figure '" + name + "': unknown (known: " + known + ")");
}

void write_bench_figure(const std::string& file, const BenchFigure& f) {
    const std::string png = ".png";
    if (file.size() > png.size() && file.compare(file.size() - png.size(), png.size(), png) == 0) {
        write_png_image(ray_diagram_image(f.diagram, f.width, f.min_height), file);
    } else {
        write_text_atomically(file, ray_diagram_svg(f.diagram, f.width, f.min_height));
    }
}

std::string bench_figure_svg(const AnalyzeResults& results, const AnalyzeRequest& request,
                             const std::string& name) {
    const BenchFigure f = bench_figure(results, request, name);
    return ray_diagram_svg(f.diagram, f.width, f.min_height);
}

}  // namespace lenslab
