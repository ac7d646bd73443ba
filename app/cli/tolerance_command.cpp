// `lenslab tolerance DESIGN`: the sensitivity table and Monte Carlo of a lens design's
// manufacturing errors (optimize/tolerance.h, docs/optimizer.md#tolerancing). Progress on
// stderr, the report on stdout as a table or JSON.

#include <algorithm>
#include <iostream>
#include <memory>
#include <optional>

#include "analysis/figures/analyze_figures.h"
#include "cluster/cluster_session.h"
#include "commands.h"
#include "optimize/lens_design_spec.h"
#include "optimize/tolerance.h"
#include "optimize/tolerance_figure.h"
#include "optimize/tolerance_report.h"
#include "render_overrides.h"
#include "util/format_number.h"
#include "util/scene_error.h"

namespace lenslab::cli {

namespace {

// `text` padded to `width` characters (not bytes: the labels hold ± and °).
std::string in_column(const std::string& text, size_t width) {
    const size_t characters = size_t(std::count_if(text.begin(), text.end(), [](char c) {
        return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    }));
    return text + std::string(width > characters ? width - characters : 0, ' ');
}

struct ToleranceArgs {
    std::string design;
    std::optional<int64_t> trials, seed;
    std::string figure;  // the Monte Carlo's histogram and yield, SVG or PNG
    bool json = false;
    bool quiet = false;
};

std::string cell(const std::optional<double>& v) {
    return v ? printf_text("%.5f", *v) : std::string("(fails)");
}

void print_table(const std::string& design, const ToleranceReport& r) {
    const bool mtf = r.higher_is_better;
    std::cout << "lenslab tolerance " << design << "\n\n"
              << "criterion: "
              << (mtf ? "polychromatic MTF, the mean over the fields; focus by the RMS spot"
                  : r.criterion == "rms_wavefront" ? "polychromatic RMS wavefront (waves), root "
                                                     "mean square over the fields"
                                                   : "polychromatic RMS spot, root mean square "
                                                     "over the fields")
              << (r.compensated ? "; each made lens refocused (back focus compensator)" : "")
              << "\n"
              << printf_text("nominal %.5f (image plane %.4f behind the last vertex)\n\n",
                             r.nominal, r.image_distance)
              << printf_text("%-36s %12s %12s\n", "tolerance", "at -", "at +");
    for (const SensitivityRow& row : r.rows) {
        std::cout << in_column(row.label, 36)
                  << printf_text(" %12s %12s\n", cell(row.minus).c_str(), cell(row.plus).c_str());
    }
    const MonteCarloSummary& m = r.monte_carlo;
    std::cout << printf_text("\nroot-sum-square of the worst changes: %.5f (nominal %s RSS %.5f)\n",
                             r.rss_change, mtf ? "-" : "+",
                             mtf ? r.nominal - r.rss_change : r.nominal + r.rss_change)
              << printf_text("the table predicts of the Monte Carlo: mean %.5f, sd %.5f\n",
                             r.predicted_mean, r.predicted_sd)
              << printf_text("Monte Carlo, %d made lenses (%d could not be evaluated):\n", m.trials,
                             m.failed)
              << printf_text("  mean %.5f, sd %.5f, min %.5f, max %.5f\n", m.mean, m.sd, m.min,
                             m.max)
              << printf_text("  50%% of lenses at or %s %.5f, 90%% %.5f, 98%% %.5f\n",
                             mtf ? "above" : "below", m.p50, m.p90, m.p98);
}

int run_tolerance(const ToleranceArgs& a) {
    LensDesign design = load_lens_design(a.design);
    if (a.trials) design.tolerances.trials = int(*a.trials);
    if (a.seed) design.tolerances.seed = uint64_t(*a.seed);
    if (tolerance_items(design).empty()) {
        throw SceneError(a.design + ": tolerances",
                         "no tolerance to try (give radius, thickness or air_gap in mm)");
    }
    ToleranceReport report;
    try {
        report = tolerance_design(design, [&a](int done, int of) {
            if (!a.quiet)
                std::cerr << "Monte Carlo: " << done << " of " << of << "\n" << std::flush;
        });
    } catch (const SceneError& e) {
        throw SceneError(a.design + ": " + e.path(), e.reason());
    }
    // Under mpirun every rank has the report; rank 0 writes the figure.
    if (!a.figure.empty() && world_communicator().rank() == 0) {
        const std::string unit = report.criterion == "rms_wavefront"                ? "waves"
                                 : report.criterion == "mtf"                        ? ""
                                 : design.scene.value("length_unit_mm", 1.0) == 1.0 ? "mm"
                                                                                    : "";
        write_bench_figure(a.figure, {tolerance_figure(report, unit), kToleranceFigureWidth,
                                      kToleranceFigureHeight});
    }
    if (a.json) {
        nlohmann::ordered_json j = tolerance_json(report);
        j["design"] = a.design;
        std::cout << j.dump(2) << "\n";
    } else {
        print_table(a.design, report);
        if (!a.figure.empty()) std::cout << "Monte Carlo figure written to " << a.figure << "\n";
    }
    return 0;
}

}  // namespace

Action add_tolerance_command(CLI::App& app) {
    auto args = std::make_shared<ToleranceArgs>();
    CLI::App* cmd = app.add_subcommand(
        "tolerance",
        "Tolerance a lens design: sensitivity table and Monte Carlo (docs/optimizer.md)");
    cmd->add_option("design", args->design, "Design file (JSON) with a `tolerances` block")
        ->required();
    const ParamSpec& trials = tolerances_spec().param("trials");
    cmd->add_option("--trials", args->trials,
                    "Made lenses of the Monte Carlo (default: the design's, else " +
                        trials.fallback.dump() + ")")
        ->check(declared_check(trials));
    cmd->add_option("--seed", args->seed, "The Monte Carlo's seed (default: the design's)")
        ->check(declared_check(tolerances_spec().param("seed")));
    cmd->add_option("--figure", args->figure,
                    "Write the Monte Carlo's histogram and cumulative yield to this file: SVG, "
                    "or PNG for a name ending in .png");
    cmd->add_flag("--json", args->json, "Print the report as JSON");
    cmd->add_flag("-q,--quiet", args->quiet, "No progress on stderr");
    return [args] { return run_tolerance(*args); };
}

}  // namespace lenslab::cli
