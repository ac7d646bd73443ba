// lenslab: render scenes and trace rays through lenses from the command line.

#include <cmath>
#include <iostream>
#include <string>

#include "commands.h"
#include "util/error.h"

namespace {

// The one check every option of every command goes through, whatever its own: a value may
// not be empty (`lenslab render ""` would read as no scene at all, the built-in default), and
// a number (FLOAT, or the NUMBER of the render overrides) must be finite: CLI11 reads "nan"
// and "inf" as numbers, and NaN passes its Range and PositiveNumber checks.
void check_every_option(CLI::App& app) {
    for (CLI::Option* option : app.get_options()) {
        if (option->get_expected_min() == 0) continue;  // a flag
        const std::string type = option->get_type_name();
        const bool number =
            type.find("FLOAT") != std::string::npos || type.find("NUMBER") != std::string::npos;
        // Added in front (transform), so it answers before the option's own checks: NaN and
        // -inf would otherwise meet a Range's "not in range 0 to 1.79e308" first.
        option->transform(CLI::Validator(
            [number](std::string& text) -> std::string {
                if (text.empty()) return "must not be empty";
                double v = 0;
                if (number && CLI::detail::lexical_cast(text, v) && !std::isfinite(v)) {
                    return "must be a finite number, got '" + text + "'";
                }
                return "";
            },
            ""));
    }
    for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
        check_every_option(*sub);
    }
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "lenslab: physically based rendering of light through lenses, and an optical bench"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "lenslab 0.1.0");
    const auto render = lenslab::cli::add_render_command(app);
    const auto trace = lenslab::cli::add_trace_command(app);
    const auto bench = lenslab::cli::add_bench_command(app);
    const auto glass = lenslab::cli::add_glass_command(app);
    const auto analyze = lenslab::cli::add_analyze_command(app);
    const auto detect = lenslab::cli::add_detect_command(app);
    check_every_option(app);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
        std::cerr << "lenslab: error: " << e.what() << "\nRun 'lenslab --help' for usage.\n";
        return 2;
    }
    try {
        if (app.got_subcommand("render")) return render();
        if (app.got_subcommand("trace")) return trace();
        if (app.got_subcommand("bench")) return bench();
        if (app.got_subcommand("glass")) return glass();
        if (app.got_subcommand("analyze")) return analyze();
        if (app.got_subcommand("detect")) return detect();
    } catch (const lenslab::Error& e) {  // the user's to fix: bad input, a full disk, ...
        std::cerr << "lenslab: error: " << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "lenslab: internal error: " << e.what() << "\n";
        return 3;
    }
    return 2;
}
