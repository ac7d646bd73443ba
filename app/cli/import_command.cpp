// `lenslab import FILE -o lens.json`: a Zemax .zmx or CODE V .seq lens file as a scene
// holding its lens_group, with the file's wavelengths, fields and aperture under "bench".
// Warnings (lines passed over) go to stderr with their line numbers.

#include <filesystem>
#include <iostream>
#include <memory>

#include "commands.h"
#include "scene/lens_file_import.h"
#include "util/atomic_file.h"
#include "util/output_path.h"

namespace lenslab::cli {

namespace {

struct ImportArgs {
    std::string file;
    std::string output;
    std::string name;
    int configuration = 0;
};

int run_import(const ImportArgs& a) {
    if (!a.output.empty()) check_output_file(a.output);  // before the work
    const std::string name =
        a.name.empty() ? std::filesystem::path(a.file).stem().string() : a.name;
    const ImportedLens lens = import_lens_file(a.file, name, 1.0, a.configuration);
    std::cerr << lens_file_warnings_text(lens, a.file);
    const std::string text = imported_scene_json(lens, a.file).dump(2) + "\n";
    if (a.output.empty()) {
        std::cout << text;
        return 0;
    }
    write_text_atomically(a.output, text);
    std::cerr << "lenslab import: " << lens.element_lines.size() << " element(s) from " << a.file
              << " written to " << a.output << "\n";
    return 0;
}

}  // namespace

Action add_import_command(CLI::App& app) {
    auto args = std::make_shared<ImportArgs>();
    CLI::App* cmd = app.add_subcommand(
        "import",
        "Read a Zemax .zmx or .zar or CODE V .seq lens file into a scene holding its lens_group "
        "(in mm)");
    cmd->add_option("file", args->file,
                    "The lens file (.zmx: UTF-16 or UTF-8; .zar: a Zemax archive; .seq)")
        ->required();
    cmd->add_option("-o,--output", args->output,
                    "Write the scene (JSON) to this file (default: standard output)");
    cmd->add_option("--name", args->name, "The lens_group's name (default: the file's stem)");
    cmd->add_option("--configuration", args->configuration,
                    "A zoom's configuration, from 1 (Zemax MNUM and THIC records; default: the "
                    "one the file's surfaces hold)")
        ->check(CLI::Range(1, 1000));
    return [args] { return run_import(*args); };
}

}  // namespace lenslab::cli
