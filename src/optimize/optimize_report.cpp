#include "optimize/optimize_report.h"

#include <algorithm>

#include "util/format_number.h"

namespace lenslab {

namespace {

std::string or_merit_block(const char* title, const MeritTable& table) {
    std::string text =
        std::string(title) +
        (table.configurations.empty()
             ? printf_text(": merit %.6g (EFL %.6g, image %.6g behind the last vertex)\n",
                           table.merit, table.efl, table.image_distance)
             : printf_text(": merit %.6g\n", table.merit));
    for (const ConfigurationRow& c : table.configurations) {
        text += printf_text("  configuration %s: EFL %.6g, image %.6g behind the last vertex\n",
                            c.name.c_str(), c.efl, c.image_distance);
    }
    text += printf_text("  %-32s %14s %14s %10s %14s\n", "operand", "value", "target", "weight",
                        "contribution");
    for (const OperandRow& row : table.operands) {
        const std::string target =
            (row.constraint ? (row.label.rfind("min", 0) == 0 ? ">= " : "<= ") : "") +
            printf_text("%.6g", row.target);
        text += printf_text("  %-32s %14.6g %14s %10.4g %14.6g\n", row.label.c_str(), row.value,
                            target.c_str(), row.weight, row.contribution);
    }
    return text;
}

nlohmann::ordered_json or_merit_json(const MeritTable& table) {
    nlohmann::ordered_json j;
    j["merit"] = table.merit;
    j["efl"] = table.efl;
    j["image_distance"] = table.image_distance;
    if (!table.configurations.empty()) {
        j["configurations"] = nlohmann::ordered_json::array();
        for (const ConfigurationRow& c : table.configurations) {
            j["configurations"].push_back(
                {{"name", c.name}, {"efl", c.efl}, {"image_distance", c.image_distance}});
        }
    }
    j["operands"] = nlohmann::ordered_json::array();
    for (const OperandRow& row : table.operands) {
        j["operands"].push_back({{"operand", row.label},
                                 {row.constraint ? "limit" : "target", row.target},
                                 {"value", row.value},
                                 {"weight", row.weight},
                                 {"contribution", row.contribution}});
    }
    return j;
}

}  // namespace

std::string optimize_table(const OptimizeResult& result) {
    std::string text = or_merit_block("before", result.before) + "\n" +
                       or_merit_block("after", result.after) + "\n";
    text += printf_text("  %-32s %16s %16s\n", "variable", "before", "after");
    for (const VariableRow& v : result.variables) {
        text += printf_text("  %-32s %16.9g %16.9g\n", v.label.c_str(), v.before, v.after);
    }
    if (!result.glass_trials.empty()) {
        text += printf_text("\n  %-32s %16s %16s\n", "glass choice", "glass", "merit");
        for (const GlassTrial& t : result.glass_trials) {
            text += printf_text("  %-32s %16s %16.6g%s\n", t.lens.c_str(), t.glass.c_str(), t.merit,
                                t.kept ? "  kept" : "");
        }
    }
    if (result.model_glass_merit) {
        text += printf_text(
            "\nglass substitution: merit %.6g with the model glasses, %.6g with catalogue glasses "
            "(%.3f times)\n",
            *result.model_glass_merit, result.after.merit,
            result.after.merit / *result.model_glass_merit);
    }
    if (result.global) {
        const GlobalSearchResult& g = *result.global;
        const auto evaluable =
            std::count_if(g.starts.begin(), g.starts.end(),
                          [](const GlobalSearchStart& s) { return s.evaluable; });
        text += printf_text("\nglobal search: %zu starts (%td evaluable), the best polished:\n",
                            g.starts.size(), evaluable);
        text += printf_text("  %8s %16s %16s\n", "start", "merit (short)", "merit (whole)");
        for (const GlobalSearchStart& s : g.starts) {
            if (!s.polished) continue;
            text += printf_text("  %8d %16.6g %16.6g%s\n", s.index, s.merit, s.polished_merit,
                                s.index == g.chosen ? "  kept" : "");
        }
    }
    text += printf_text("\n%d iterations, %d evaluations: ", result.solver.iterations,
                        result.solver.evaluations) +
            result.solver.stopped + "\n";
    return text;
}

nlohmann::ordered_json optimize_json(const OptimizeResult& result) {
    nlohmann::ordered_json j;
    j["before"] = or_merit_json(result.before);
    j["after"] = or_merit_json(result.after);
    j["variables"] = nlohmann::ordered_json::array();
    for (const VariableRow& v : result.variables) {
        j["variables"].push_back({{"variable", v.label}, {"before", v.before}, {"after", v.after}});
    }
    if (!result.glass_trials.empty()) {
        j["glass_trials"] = nlohmann::ordered_json::array();
        for (const GlassTrial& t : result.glass_trials) {
            j["glass_trials"].push_back(
                {{"lens", t.lens}, {"glass", t.glass}, {"merit", t.merit}, {"kept", t.kept}});
        }
    }
    if (result.model_glass_merit) {
        j["glass_substitution"] = {{"model_merit", *result.model_glass_merit},
                                   {"merit", result.after.merit},
                                   {"ratio", result.after.merit / *result.model_glass_merit}};
    }
    if (result.global) {
        nlohmann::ordered_json g;
        g["starts"] = nlohmann::ordered_json::array();
        for (const GlobalSearchStart& s : result.global->starts) {
            nlohmann::ordered_json start = {{"start", s.index}, {"evaluable", s.evaluable}};
            if (s.evaluable) start["merit"] = s.merit;
            if (s.polished) start["polished_merit"] = s.polished_merit;
            g["starts"].push_back(start);
        }
        g["chosen"] = result.global->chosen;
        j["global_search"] = g;
    }
    j["iterations"] = result.solver.iterations;
    j["evaluations"] = result.solver.evaluations;
    j["stopped"] = result.solver.stopped;
    return j;
}

}  // namespace lenslab
