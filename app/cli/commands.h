#pragma once
// The `lenslab` subcommands. Each registers its options and returns the action to run
// when it is chosen; the action returns the process exit code.

#include <CLI/CLI.hpp>
#include <functional>
#include <string>

namespace lenslab::cli {

using Action = std::function<int()>;

// The check of a whole-number option: "must be a whole number, got '1.5'" (CLI11's own
// TypeValidator says "Failed parsing 1.5 as a INT"). The help still shows the type as INT.
template <class T>
CLI::Validator whole_number() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            T value{};
            if (CLI::detail::lexical_cast(text, value)) return "";
            return "must be a whole number, got '" + text + "'";
        },
        CLI::detail::type_name<T>());
}

Action add_render_command(CLI::App& app);
Action add_trace_command(CLI::App& app);
Action add_bench_command(CLI::App& app);
// `bench povray`, registered by add_bench_command under its `bench`.
Action add_bench_povray_command(CLI::App& bench);
// `bench optimize`, likewise.
Action add_bench_optimize_command(CLI::App& bench);
Action add_glass_command(CLI::App& app);
Action add_analyze_command(CLI::App& app);
Action add_detect_command(CLI::App& app);
Action add_import_command(CLI::App& app);
Action add_export_command(CLI::App& app);
Action add_optimize_command(CLI::App& app);
Action add_tolerance_command(CLI::App& app);
Action add_sweep_command(CLI::App& app);
Action add_types_command(CLI::App& app);
Action add_spectra_command(CLI::App& app);
Action add_colour_speckle_command(CLI::App& app);

}  // namespace lenslab::cli
