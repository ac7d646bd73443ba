// lenslab: render scenes and trace rays through lenses from the command line.

#include <iostream>

#include "commands.h"
#include "util/error.h"

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
