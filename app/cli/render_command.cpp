// `lenslab render [SCENE] -o OUT`: render a scene file, or the built-in default scene.

#include <tbb/info.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <iostream>
#include <memory>

#include "cluster/cluster_session.h"
#include "commands.h"
#include "render/image_io.h"
#include "render/render_session.h"
#include "render_overrides.h"
#include "scene/render_settings.h"
#include "util/output_path.h"

namespace lenslab::cli {

namespace {

struct RenderArgs {
    std::string scene;
    std::string output = "lenslab.png";
    int threads = 0;
    double exposure = 0.0;
    bool quiet = false;
};

RenderControl* g_control = nullptr;

std::string format_seconds(double s) {
    char text[32];
    std::snprintf(text, sizeof text, "%g s", s);
    return text;
}

extern "C" void on_interrupt(int) {
    if (g_control) g_control->cancel();  // an atomic store: safe in a signal handler
}

// Prints "rendering ... 42%" on stderr: in place on a terminal, every 10% otherwise.
class ProgressPrinter {
public:
    explicit ProgressPrinter(std::string label) : m_label(std::move(label)), m_tty(isatty(2)) {}
    void operator()(double fraction) {
        const int percent = static_cast<int>(fraction * 100.0);
        const int step = m_tty ? 1 : 10;
        if (percent / step == m_last / step) return;
        m_last = percent;
        std::fprintf(stderr, m_tty ? "\r%s %3d%%" : "%s %3d%%\n", m_label.c_str(), percent);
        if (m_tty && percent == 100) std::fputc('\n', stderr);
    }

private:
    std::string m_label;
    bool m_tty;
    int m_last = -1;
};

// `--passes 0` (or `--time 0` leaving no limit) with no time budget anywhere: refused as an
// option error before any work, naming the options rather than the file's keys.
bool unbounded_passes(const RenderOverrides& overrides, const nlohmann::json& root) {
    if (!overrides.given("passes") && !overrides.given("time")) return false;
    const nlohmann::json& r = root["render"];
    const RenderSettings d;
    const auto number = [&r](const char* key, double fallback) {
        return r.is_object() && r.contains(key) && r[key].is_number() ? r[key].get<double>()
                                                                      : fallback;
    };
    return number("passes", d.passes) == 0 && number("time", d.time) == 0;
}

int run(const RenderArgs& a, const RenderOverrides& overrides) {
    if (!is_supported_image_path(a.output)) {
        std::cerr << "lenslab: error: --output '" << a.output
                  << "': unknown image type (use a .png or .exr file name)\n";
        return 2;
    }
    check_output_file(a.output);  // before the render: a read-only target fails at once
    const nlohmann::json root = overrides.patched_json(a.scene);
    if (unbounded_passes(overrides, root)) {
        std::cerr << "lenslab: error: --passes 0 means no pass limit, which needs a time budget "
                     "(--time)\n";
        return 2;
    }
    const Scene scene = overrides.scene_from(root, a.scene);
    const RenderSettings& s = scene.render;

    const int threads = a.threads > 0 ? a.threads : tbb::info::default_concurrency();
    const bool progressive = integrator_info(s.integrator).progressive;
    std::string amount = std::to_string(s.spp) + " spp";
    if (progressive) {
        amount = s.passes > 0 ? std::to_string(s.passes) + " passes" : "";
        if (s.time > 0) amount += (amount.empty() ? "" : " or ") + format_seconds(s.time);
    }
    const int ranks = world_communicator().size();
    const std::string label = "rendering " + std::to_string(s.width) + "x" +
                              std::to_string(s.height) + ", " + s.integrator + ", " + amount +
                              ", " + std::to_string(threads) + " thread" +
                              (threads > 1 ? "s" : "") +
                              (ranks > 1 ? " x " + std::to_string(ranks) + " ranks" : "") + ":";
    ProgressPrinter printer(label);
    RenderControl control(a.quiet ? RenderControl::ProgressFn{}
                                  : RenderControl::ProgressFn{std::ref(printer)});
    g_control = &control;
    // Under mpirun or srun the ranks share the render; rank 0 writes the image.
    Communicator& world = world_communicator();
    control.set_cluster(world);
    // The first Ctrl-C asks the render to stop; SA_RESETHAND makes a second one end the
    // process at once.
    struct sigaction action {};
    action.sa_handler = on_interrupt;
    action.sa_flags = SA_RESETHAND;
    sigaction(SIGINT, &action, nullptr);
    const RenderResult result = render_scene(scene, control, threads);
    if (result.cancelled) {
        signal(SIGINT, SIG_DFL);
        g_control = nullptr;
        std::cerr << "\nlenslab: render cancelled; nothing written\n";
        return 130;
    }
    if (!world.is_root()) {
        signal(SIGINT, SIG_DFL);
        g_control = nullptr;
        return 0;
    }
    if (!result.stats.summary.empty() && !a.quiet)
        std::fprintf(stderr, "%s\n", result.stats.summary.c_str());
    if (control.non_finite_samples() > 0) {
        std::fprintf(stderr,
                     "lenslab: warning: %lld samples came out NaN or infinite and were left out of "
                     "their pixels (a bug in lenslab; please report it with the scene)\n",
                     static_cast<long long>(control.non_finite_samples()));
    }
    // The file is written atomically; holding Ctrl-C (and kill's SIGTERM) back until it is
    // in place also leaves no temporary file behind. One that came meanwhile ends the
    // process right after.
    sigset_t interrupts, previous;
    sigemptyset(&interrupts);
    sigaddset(&interrupts, SIGINT);
    sigaddset(&interrupts, SIGTERM);
    sigprocmask(SIG_BLOCK, &interrupts, &previous);
    signal(SIGINT, SIG_DFL);
    g_control = nullptr;
    try {
        write_image(result.film, a.output, a.exposure);
    } catch (...) {
        sigprocmask(SIG_SETMASK, &previous, nullptr);
        throw;
    }
    sigprocmask(SIG_SETMASK, &previous, nullptr);
    if (result.stats.passes > 0) {
        std::printf("wrote %s (%dx%d, %d passes, %.2f s)\n", a.output.c_str(), s.width, s.height,
                    result.stats.passes, result.seconds);
    } else {
        std::printf("wrote %s (%dx%d, %d spp, %.2f s)\n", a.output.c_str(), s.width, s.height,
                    s.spp, result.seconds);
    }
    return 0;
}

}  // namespace

Action add_render_command(CLI::App& app) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* cmd = app.add_subcommand("render", "Render a scene to an image (PNG or EXR)");
    cmd->add_option("scene", args->scene, "Scene file (JSON); omit for the built-in default scene");
    cmd->add_option("-o,--output", args->output, "Output image: .png (sRGB) or .exr (linear)")
        ->capture_default_str();
    cmd->add_option("--threads", args->threads, "Worker threads (default: all cores)")
        ->check(whole_number<int>())
        ->check(CLI::Range(1, 1024));
    cmd->add_option("--exposure", args->exposure, "Exposure in stops applied before writing")
        ->capture_default_str()
        ->check(CLI::Range(-64.0, 64.0));
    cmd->add_flag("-q,--quiet", args->quiet, "No progress on stderr");
    // --width ... --initial-radius: generated from the render block's declaration.
    auto overrides = std::make_shared<RenderOverrides>(*cmd);
    return [args, overrides] { return run(*args, *overrides); };
}

}  // namespace lenslab::cli
