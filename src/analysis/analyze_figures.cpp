#include "analysis/analyze_figures.h"

#include "analysis/curve_figures.h"
#include "analysis/field_figures.h"
#include "analysis/ray_diagram.h"
#include "analysis/ray_diagram_svg.h"

namespace lenslab {

namespace {

// The sizes analyze_request.cpp writes its figure files at: the ray diagram 1200 wide and at
// least 360 high, the others field_figure_width(panels) wide and at least 300 high.
std::string field_svg(const RayDiagram& figure, int panels) {
    return ray_diagram_svg(figure, field_figure_width(panels), 300);
}

[[noreturn]] void not_asked(const std::string& name, const std::string& option) {
    throw AnalyzeRequestError("figure '" + name + "': it needs --" + option +
                              ", which was not asked for");
}

}  // namespace

const std::vector<std::string>& bench_figure_names() {
    static const std::vector<std::string> names{"ray_diagram",  "spots",       "fans",
                                                "field_curves", "focal_shift", "mtf"};
    return names;
}

std::string bench_figure_svg(const AnalyzeResults& r, const AnalyzeRequest& request,
                             const std::string& name) {
    const std::string& unit = request.unit;
    const std::string field_unit =
        request.object_distance > 0 ? (unit.empty() ? "units" : unit) : "deg";
    if (name == "ray_diagram") {
        RayDiagramOptions diagram;
        diagram.unit = unit;
        return ray_diagram_svg(make_ray_diagram(r.system, r.report, diagram), 1200, 360);
    }
    if (name == "spots") {
        if (!r.spots) not_asked(name, "spots");
        return field_svg(spot_diagram_figure(*r.spots, unit, field_unit),
                         static_cast<int>(r.spots->fields.size()));
    }
    if (name == "fans") {
        if (!r.fans) not_asked(name, "fans");
        return field_svg(ray_fan_figure(*r.fans, unit, field_unit), 2);
    }
    if (name == "field_curves") {
        if (!r.curves) not_asked(name, "field-curves");
        return field_svg(field_curves_figure(*r.curves, unit, field_unit), 2);
    }
    if (name == "focal_shift") {
        if (!r.shift) not_asked(name, "focal-shift");
        return field_svg(focal_shift_figure(*r.shift, unit), 1);
    }
    if (name == "mtf") {
        if (!r.diffraction || !request.mtf) not_asked(name, "mtf");
        return field_svg(mtf_figure(*r.diffraction, unit), 1);
    }
    std::string known;
    for (const std::string& n : bench_figure_names()) known += (known.empty() ? "" : ", ") + n;
    throw AnalyzeRequestError("figure '" + name + "': unknown (known: " + known + ")");
}

}  // namespace lenslab
