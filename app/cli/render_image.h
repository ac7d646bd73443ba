#pragma once
// Rendering one scene to one image file, as `lenslab render` does it: the options (--threads,
// --exposure, --quiet and the render block's overrides), progress on stderr, Ctrl-C, and an
// atomic write. `lenslab render` renders one image with it, `lenslab sweep` one per frame.

#include <CLI/CLI.hpp>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "cluster/communicator.h"
#include "render_overrides.h"
#include "scene/scene.h"

namespace lenslab::cli {

struct RenderImageOptions {
    int threads = 0;  // 0: all cores
    double exposure = 0.0;
    bool quiet = false;
    std::shared_ptr<RenderOverrides> overrides;  // --width ... --initial-radius
};

// Adds --threads, --exposure, -q/--quiet and the render overrides to `cmd`; their values go
// into `options`, which must outlive the parse.
void add_render_image_options(CLI::App& cmd, RenderImageOptions& options);

// `--passes 0` (or `--time 0` leaving no limit) with no time budget anywhere: the message
// naming the options, for a scene `root` from RenderOverrides::patched_json.
std::optional<std::string> unbounded_passes_error(const RenderOverrides& overrides,
                                                  const nlohmann::json& root);

// What render_image did.
enum class RenderImageOutcome { Written, Cancelled };

// Renders `scene` and writes it to `output` (PNG or EXR) atomically, with progress on stderr
// unless quiet and "wrote ..." on stdout. Ctrl-C cancels the render and writes nothing.
// `cluster`: the ranks that share the render (`lenslab render` under mpirun); its root writes
// the image, the others return Written having written nothing.
RenderImageOutcome render_image(const Scene& scene, const RenderImageOptions& options,
                                const std::string& output,
                                Communicator& cluster = this_process_alone());

}  // namespace lenslab::cli
