// `lenslab bench optimize [DESIGN]`: times `lenslab optimize` on a design (by default the
// issue's triplet from three flat plates, examples/optimize/triplet.design.json) and prints
// the wall time of each run with the solver's work and the result's figures.

#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#include "commands.h"
#include "optimize/optimize_design.h"

namespace lenslab::cli {

namespace {

struct BenchOptimizeArgs {
    std::string design = "examples/optimize/triplet.design.json";
    int repeats = 1;
    int threads = 0;  // 0: all cores
};

int run_bench_optimize(const BenchOptimizeArgs& a) {
    std::optional<tbb::global_control> threads;
    if (a.threads > 0) {
        threads.emplace(tbb::global_control::max_allowed_parallelism,
                        static_cast<size_t>(a.threads));
    }
    const LensDesign design = load_lens_design(a.design);
    std::vector<double> seconds;
    OptimizeResult result;
    for (int run = 1; run <= a.repeats; ++run) {
        const auto start = std::chrono::steady_clock::now();
        result = optimize_design(design);
        seconds.push_back(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        char line[200];
        std::snprintf(line, sizeof line,
                      "run %d: %.2f s wall, %d iterations, %d evaluations (%.2f ms each)\n", run,
                      seconds.back(), result.solver.iterations, result.solver.evaluations,
                      1e3 * seconds.back() / result.solver.evaluations);
        std::cout << line << std::flush;
    }
    std::sort(seconds.begin(), seconds.end());
    char line[200];
    std::snprintf(line, sizeof line, "median %.2f s; merit %.6g -> %.6g, EFL %.6g\n",
                  seconds[seconds.size() / 2], result.before.merit, result.after.merit,
                  result.after.efl);
    std::cout << "lenslab bench optimize " << a.design << "\n" << line;
    for (const OperandRow& row : result.after.operands) {
        std::snprintf(line, sizeof line, "  %-32s %.6g\n", row.label.c_str(), row.value);
        std::cout << line;
    }
    return 0;
}

}  // namespace

Action add_bench_optimize_command(CLI::App& bench) {
    auto args = std::make_shared<BenchOptimizeArgs>();
    CLI::App* cmd = bench.add_subcommand(
        "optimize", "Time the lens optimiser on a design (default: the triplet of the docs)");
    cmd->add_option("design", args->design, "Design file (JSON)")->capture_default_str();
    cmd->add_option("--repeats", args->repeats, "Runs to time (the median is printed)")
        ->capture_default_str()
        ->check(whole_number<int>())
        ->check(CLI::Range(1, 100));
    cmd->add_option("--threads", args->threads, "Worker threads (default: all cores)")
        ->check(whole_number<int>())
        ->check(CLI::Range(1, 1024));
    return [args] { return run_bench_optimize(*args); };
}

}  // namespace lenslab::cli
