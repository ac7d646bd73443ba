#include "cli_parse.h"

#include <cmath>
#include <iostream>

#include "optics/glass_catalogue_file.h"
#include "optics/user_glass_catalogues.h"

namespace lenslab::cli {

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

CommandLine::CommandLine()
    : m_app("lenslab: physically based rendering of light through lenses, and an optical bench") {
    m_app.require_subcommand(1);
    m_app.set_version_flag("--version", "lenslab 0.1.0");
    m_commands = {{"render", add_render_command(m_app)},
                  {"trace", add_trace_command(m_app)},
                  {"bench", add_bench_command(m_app)},
                  {"glass", add_glass_command(m_app)},
                  {"analyze", add_analyze_command(m_app)},
                  {"detect", add_detect_command(m_app)},
                  {"import", add_import_command(m_app)},
                  {"export", add_export_command(m_app)},
                  {"optimize", add_optimize_command(m_app)},
                  {"tolerance", add_tolerance_command(m_app)},
                  {"sweep", add_sweep_command(m_app)},
                  {"types", add_types_command(m_app)},
                  {"spectra", add_spectra_command(m_app)},
                  {"colour-speckle", add_colour_speckle_command(m_app)}};
    // A user's AGF glass catalogue for every command that reads a scene or looks up a glass.
    for (const char* name : {"render", "trace", "glass", "analyze", "detect", "import", "export",
                             "optimize", "tolerance", "sweep"}) {
        m_app.get_subcommand(name)
            ->add_option("--catalogue", m_catalogues,
                         "A Zemax AGF glass catalogue whose glasses scenes and lookups may name "
                         "(NAME or FILESTEM:NAME); repeat for several")
            ->check(CLI::ExistingFile);
    }
    for (auto& [name, action] : m_commands) {
        action = [this, inner = std::move(action)]() -> int {
            for (const std::string& file : m_catalogues) {
                try {
                    load_user_glass_catalogue(file);
                } catch (const GlassDataError& e) {
                    std::cerr << "lenslab: error: --catalogue: " << e.what() << "\n";
                    return 1;
                }
            }
            return inner();
        };
    }
    check_every_option(m_app);
}

const Action* CommandLine::chosen() const {
    for (const auto& [name, action] : m_commands)
        if (m_app.got_subcommand(name)) return &action;
    return nullptr;
}

namespace {

bool is_command_name(const CLI::App& app, const std::string& name) {
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
        if ((!name.empty() && sub->get_name() == name) || is_command_name(*sub, name)) return true;
    return false;
}

}  // namespace

void CommandLine::parse(int argc, const char* const* argv) {
    // An empty argument is a value of the option before it, or the scene right after the
    // command's name ("scene: must not be empty" says so). Anywhere else CLI11 takes it for
    // the name of an option group, all of which are named "", and `sweep` (the only command
    // with groups) then looped for ever on the next unknown option (found by fuzz_argv).
    for (int i = 2; i < argc; ++i) {
        const std::string before = argv[i - 1];
        if (argv[i][0] == '\0' && !before.starts_with('-') && !is_command_name(m_app, before))
            throw CLI::ValidationError("argument " + std::to_string(i) +
                                       ": empty, and not the value of an option");
    }
    m_app.parse(argc, argv);
}

}  // namespace lenslab::cli
