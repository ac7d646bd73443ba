// `lenslab export SCENE --object NAME -o lens.zmx`: a lens_group (or a prescription lens) of a
// scene written as a Zemax .zmx file, so a design made here opens elsewhere.

#include <iostream>
#include <memory>

#include "commands.h"
#include "lensfile/lens_file.h"
#include "lensfile/zmx_writer.h"
#include "scene/scene_json.h"
#include "util/atomic_file.h"
#include "util/output_path.h"
#include "util/scene_error.h"

namespace lenslab::cli {

namespace {

struct ExportArgs {
    std::string scene;
    std::string object;
    std::string output;
};

int run_export(const ExportArgs& a) {
    check_output_file(a.output);
    // Read as a scene first, so only a lens the scene reader accepts is written.
    const nlohmann::json root = read_scene_json_file(a.scene);
    (void)scene_from_file_json(root, a.scene, {.require_camera = false});
    const nlohmann::json objects = root.value("objects", nlohmann::json::array());
    std::string known;
    for (size_t i = 0; i < objects.size(); ++i) {
        const nlohmann::json& o = objects[i];
        const std::string path = "objects[" + std::to_string(i) + "]";
        const std::string name = o.value("name", path);
        const std::string type = o.value("type", std::string());
        if (type != "lens_group" && type != "lens") continue;
        known += (known.empty() ? "" : ", ") + name;
        if (name != a.object && path != a.object) continue;
        const std::string text =
            zmx_from_lens_object(o, path, root.value("materials", nlohmann::json::object()),
                                 root.value("bench", nlohmann::json()));
        write_text_atomically(a.output, text);
        std::cerr << "lenslab export: " << name << " written to " << a.output << "\n";
        return 0;
    }
    std::cerr << "lenslab: error: --object: no lens_group or lens named '" << a.object << "' in "
              << a.scene << (known.empty() ? " (it has none)" : " (lenses: " + known + ")") << "\n";
    return 2;
}

}  // namespace

Action add_export_command(CLI::App& app) {
    auto args = std::make_shared<ExportArgs>();
    CLI::App* cmd = app.add_subcommand(
        "export",
        "Write a scene's lens_group (or prescription lens) as a Zemax .zmx file (UTF-8, mm)");
    cmd->add_option("scene", args->scene, "Scene file (JSON)")->required();
    cmd->add_option("--object", args->object, "The lens to write: its name or objects[i]")
        ->required();
    cmd->add_option("-o,--output", args->output, "The .zmx file to write")->required();
    return [args] { return run_export(*args); };
}

}  // namespace lenslab::cli
