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
    m_commands = {{"render", add_render_command(m_app)},     {"trace", add_trace_command(m_app)},
                  {"bench", add_bench_command(m_app)},       {"glass", add_glass_command(m_app)},
                  {"analyze", add_analyze_command(m_app)},   {"detect", add_detect_command(m_app)},
                  {"import", add_import_command(m_app)},     {"export", add_export_command(m_app)},
                  {"optimize", add_optimize_command(m_app)}, {"sweep", add_sweep_command(m_app)},
                  {"types", add_types_command(m_app)}};
    // A user's AGF glass catalogue for every command that reads a scene or looks up a glass.
    for (const char* name : {"render", "trace", "glass", "analyze", "detect", "import", "export",
                             "optimize", "sweep"}) {
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

}  // namespace lenslab::cli
