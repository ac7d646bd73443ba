// `lenslab render [SCENE] -o OUT`: render a scene file, or the built-in default scene.

#include <iostream>
#include <memory>

#include "cluster/cluster_session.h"
#include "commands.h"
#include "image/image_io.h"
#include "render_image.h"
#include "util/output_path.h"

namespace lenslab::cli {

namespace {

struct RenderArgs {
    std::string scene;
    std::string output = "lenslab.png";
    RenderImageOptions image;
};

int run(const RenderArgs& a) {
    if (!is_supported_image_path(a.output)) {
        std::cerr << "lenslab: error: --output '" << a.output
                  << "': unknown image type (use a .png or .exr file name)\n";
        return 2;
    }
    check_output_file(a.output);  // before the render: a read-only target fails at once
    const RenderOverrides& overrides = *a.image.overrides;
    const nlohmann::json root = overrides.patched_json(a.scene);
    if (const auto error = unbounded_passes_error(overrides, root)) {
        std::cerr << "lenslab: error: " << *error << "\n";
        return 2;
    }
    const Scene scene = overrides.scene_from(root, a.scene);
    // Under mpirun or srun the ranks share the render; rank 0 writes the image.
    return render_image(scene, a.image, a.output, world_communicator()) ==
                   RenderImageOutcome::Written
               ? 0
               : 130;
}

}  // namespace

Action add_render_command(CLI::App& app) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* cmd = app.add_subcommand("render", "Render a scene to an image (PNG or EXR)");
    cmd->add_option("scene", args->scene, "Scene file (JSON); omit for the built-in default scene");
    cmd->add_option("-o,--output", args->output, "Output image: .png (sRGB) or .exr (linear)")
        ->capture_default_str();
    add_render_image_options(*cmd, args->image);
    return [args] { return run(*args); };
}

}  // namespace lenslab::cli
