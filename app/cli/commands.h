#pragma once
// The `lenslab` subcommands. Each registers its options and returns the action to run
// when it is chosen; the action returns the process exit code.

#include <CLI/CLI.hpp>
#include <functional>

namespace lenslab::cli {

using Action = std::function<int()>;

Action add_render_command(CLI::App& app);
Action add_trace_command(CLI::App& app);
Action add_bench_command(CLI::App& app);
// `bench povray`, registered by add_bench_command under its `bench`.
Action add_bench_povray_command(CLI::App& bench);
Action add_glass_command(CLI::App& app);
Action add_analyze_command(CLI::App& app);
Action add_detect_command(CLI::App& app);

}  // namespace lenslab::cli
