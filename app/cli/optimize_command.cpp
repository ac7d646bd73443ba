// `lenslab optimize DESIGN -o OUT`: damped least squares on a lens design
// (docs/optimizer.md). Progress on stderr, the merit function and every operand before and
// after on stdout, the optimised scene written to OUT.

#include <filesystem>
#include <iostream>
#include <memory>

#include "cluster/cluster_session.h"
#include "commands.h"
#include "optimize/lens_design_spec.h"
#include "optimize/optimize_report.h"
#include "render_overrides.h"
#include "util/atomic_file.h"
#include "util/format_number.h"
#include "util/scene_error.h"

namespace lenslab::cli {

namespace {

struct OptimizeArgs {
    std::string design;
    std::string output;
    int iterations = -1;     // -1: the design's
    int global_starts = -1;  // -1: the design's global_search block; 0: none
    bool json = false;
    bool quiet = false;
};

int run_optimize(const OptimizeArgs& a) {
    check_output_file(a.output);  // before the work, not after
    LensDesign design = load_lens_design(a.design);
    if (a.global_starts >= 0) design.global_search.starts = a.global_starts;
    const int starts = design.global_search.starts;
    const int runs = global_search_runs(design.global_search);
    const auto progress = [&a, starts, runs](const LmProgress& p) {
        if (a.quiet) return;
        const std::string line =
            starts > 0 ? printf_text(
                             "global search: %d of %d runs ended, best merit %.6g, %d "
                             "evaluations\n",
                             p.iteration, runs, p.merit, p.evaluations)
                       : printf_text("iteration %d: merit %.6g, damping %.3g, %d evaluations\n",
                                     p.iteration, p.merit, p.damping, p.evaluations);
        std::cerr << line << std::flush;
    };
    OptimizeResult result;
    try {
        const auto on_glass = [&a](const GlassTrial& t) {
            if (a.quiet) return;
            std::cerr << printf_text("glass %s %s: merit %.6g%s\n", t.lens.c_str(), t.glass.c_str(),
                                     t.merit, t.kept ? " (best so far)" : "")
                      << std::flush;
        };
        result = optimize_design(design, a.iterations, progress, on_glass);
    } catch (const SceneError& e) {
        throw SceneError(a.design + ": " + e.path(), e.reason());
    }
    // A multi-configuration design's other configurations beside it: zoom.json, zoom.tele.json.
    std::vector<std::string> outputs;
    for (const auto& [name, scene] : result.configuration_scenes) {
        const std::filesystem::path out(a.output);
        outputs.push_back(
            (out.parent_path() / (out.stem().string() + "." + name + out.extension().string()))
                .string());
    }
    // Under mpirun every rank has the result; rank 0 writes it.
    if (world_communicator().rank() == 0) {
        write_text_atomically(a.output, result.scene.dump(2) + "\n");
        for (size_t k = 0; k < outputs.size(); ++k) {
            write_text_atomically(outputs[k], result.configuration_scenes[k].second.dump(2) + "\n");
        }
    }
    if (a.json) {
        nlohmann::ordered_json j = optimize_json(result);
        j["design"] = a.design;
        j["output"] = a.output;
        if (!outputs.empty()) j["configuration_outputs"] = outputs;
        std::cout << j.dump(2) << "\n";
    } else {
        std::cout << "lenslab optimize " << a.design << "\n\n"
                  << optimize_table(result) << "optimised system written to " << a.output;
        if (!result.configuration_scenes.empty())
            std::cout << " (" << design.configurations[0].name << ")";
        std::cout << "\n";
        for (size_t k = 0; k < outputs.size(); ++k) {
            std::cout << "configuration " << result.configuration_scenes[k].first << " written to "
                      << outputs[k] << "\n";
        }
    }
    return 0;
}

}  // namespace

Action add_optimize_command(CLI::App& app) {
    auto args = std::make_shared<OptimizeArgs>();
    CLI::App* cmd = app.add_subcommand(
        "optimize", "Optimise a lens design by damped least squares (docs/optimizer.md)");
    cmd->add_option("design", args->design, "Design file (JSON): system, variables, operands")
        ->required();
    cmd->add_option("-o,--output", args->output,
                    "Write the optimised system here (the scene file with the new values)")
        ->required();
    const ParamSpec& iterations = lens_design_spec().param("iterations");
    cmd->add_option("--iterations", args->iterations,
                    "Most iterations of the solver (default: the design's `iterations`, else " +
                        iterations.fallback.dump() + ")")
        ->check(declared_check(iterations));
    const ParamSpec& starts = global_search_spec().param("starts");
    cmd->add_option("--global-starts", args->global_starts,
                    "Start the solver from N points spread over the variables' region and keep "
                    "the best (0: only the design's start; default: the design's global_search "
                    "block, else 0)")
        ->check(CLI::Range(0.0, starts.max->value));
    cmd->add_flag("--json", args->json, "Print the before/after report as JSON");
    cmd->add_flag("-q,--quiet", args->quiet, "No progress on stderr");
    return [args] { return run_optimize(*args); };
}

}  // namespace lenslab::cli
