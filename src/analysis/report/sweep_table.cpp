#include "analysis/report/sweep_table.h"

#include <algorithm>

namespace lenslab {

namespace {

using nlohmann::ordered_json;

// A CSV cell: quoted when it holds a comma, a quote or a line break (RFC 4180).
std::string csv_cell(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
    std::string out = "\"";
    for (char c : text) {
        if (c == '"') out += '"';
        out += c;
    }
    return out + "\"";
}

// Appends ",text" to a line of the table.
void append_cell(std::string& line, const std::string& text) {
    line += ',';
    line += text;
}

// Every figure of every frame, each once, in the order they first appear.
std::vector<std::string> figure_columns(const std::vector<ordered_json>& reports) {
    std::vector<std::string> columns;
    for (const ordered_json& report : reports) {
        for (const auto& [name, value] : bench_figures(report)) {
            if (std::find(columns.begin(), columns.end(), name) == columns.end())
                columns.push_back(name);
        }
    }
    return columns;
}

bool is_figure(const ordered_json& value) { return value.is_number() && !value.is_boolean(); }

}  // namespace

std::vector<std::pair<std::string, ordered_json>> bench_figures(const ordered_json& report) {
    std::vector<std::pair<std::string, ordered_json>> figures;
    for (const auto& [key, value] : report.items()) {
        if (is_figure(value)) figures.emplace_back(key, value);
        if (!value.is_object()) continue;
        for (const auto& [inner, number] : value.items()) {
            if (is_figure(number)) figures.emplace_back(key + "." + inner, number);
        }
    }
    return figures;
}

std::string sweep_csv(const SweepPlan& plan, const std::vector<ordered_json>& reports) {
    const std::vector<std::string> columns = figure_columns(reports);
    std::string csv = "frame";
    for (const SweepParameter& p : plan.parameters) append_cell(csv, csv_cell(p.pointer));
    for (const std::string& column : columns) append_cell(csv, csv_cell(column));
    csv += "\n";
    for (size_t frame = 0; frame < reports.size(); ++frame) {
        csv += std::to_string(frame);
        for (const SweepParameter& p : plan.parameters)
            append_cell(csv, ordered_json(sweep_value(p, static_cast<int>(frame))).dump());
        const auto figures = bench_figures(reports[frame]);
        for (const std::string& column : columns) {
            csv += ",";
            const auto it = std::find_if(figures.begin(), figures.end(),
                                         [&column](const auto& f) { return f.first == column; });
            if (it != figures.end()) csv += it->second.dump();
        }
        csv += "\n";
    }
    return csv;
}

ordered_json sweep_summary_json(const SweepPlan& plan, const std::string& scene_file,
                                const std::vector<std::string>& frame_files,
                                const std::vector<ordered_json>& reports) {
    ordered_json j;
    j["scene"] = scene_file;
    j["count"] = plan.count;
    j["parameters"] = ordered_json::array();
    for (const SweepParameter& p : plan.parameters) {
        j["parameters"].push_back(
            {{"pointer", p.pointer}, {"from", p.from}, {"to", p.to}, {"count", p.count}});
    }
    j["frames"] = ordered_json::array();
    for (size_t frame = 0; frame < frame_files.size(); ++frame) {
        ordered_json f;
        f["frame"] = frame;
        f["file"] = frame_files[frame];
        f["values"] = ordered_json::object();
        for (const SweepParameter& p : plan.parameters)
            f["values"][p.pointer] = sweep_value(p, static_cast<int>(frame));
        if (frame < reports.size()) {
            f["figures"] = ordered_json::object();
            for (const auto& [name, value] : bench_figures(reports[frame]))
                f["figures"][name] = value;
        }
        j["frames"].push_back(f);
    }
    return j;
}

}  // namespace lenslab
