// `lenslab render [SCENE] -o OUT`: render a scene file, or the built-in default scene.

#include <cmath>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <memory>
#include <unistd.h>

#include <tbb/info.h>

#include "commands.h"
#include "render/image_io.h"
#include "render/render_session.h"
#include "scene/limits.h"
#include "scene/scene_json.h"

namespace lenslab::cli {

namespace {

struct RenderArgs {
    std::string scene;
    std::string output = "lenslab.png";
    int width = 0, height = 0, spp = 0, max_depth = -1, threads = 0;
    int64_t seed = -1;
    std::string integrator, filter, direct;
    int64_t photons = 0, caustic_photons = 0;
    std::string aim_photons;
    double radius = 0, filter_k = 0;
    int max_photons_per_estimate = 0;
    int passes = -1;
    double time = -1;
    int64_t pass_photons = 0;
    double initial_radius = 0;
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

int run(const RenderArgs& a) {
    if (!is_supported_image_path(a.output)) {
        std::cerr << "lenslab: error: --output '" << a.output
                  << "': unknown image type (use a .png or .exr file name)\n";
        return 2;
    }
    if (!std::isfinite(a.exposure)) {  // CLI11's range check lets NaN through
        std::cerr << "lenslab: error: --exposure: must be a number of stops between -64 and 64\n";
        return 2;
    }
    Scene scene = a.scene.empty() ? default_scene() : load_scene_file(a.scene);
    RenderSettings& s = scene.render;
    if (a.width > 0) s.width = a.width;
    if (a.height > 0) s.height = a.height;
    if (a.spp > 0) s.spp = a.spp;
    if (a.max_depth >= 0) s.max_depth = a.max_depth;
    if (a.seed >= 0) s.seed = static_cast<uint64_t>(a.seed);
    if (!a.integrator.empty()) s.integrator = a.integrator;
    if (a.photons > 0) s.photons = a.photons;
    if (a.caustic_photons > 0) s.caustic_photons = a.caustic_photons;
    if (!a.aim_photons.empty()) s.aim_photons = a.aim_photons == "on";
    if (a.radius > 0) s.radius = a.radius;
    if (!a.filter.empty()) s.filter = a.filter;
    if (!a.direct.empty()) s.direct = a.direct;
    if (a.filter_k > 0) s.filter_k = a.filter_k;
    if (a.max_photons_per_estimate > 0) s.max_photons_per_estimate = a.max_photons_per_estimate;
    if (a.time >= 0) {
        s.time = a.time;
        if (a.passes < 0) s.passes = 0;  // a time budget alone: as many passes as fit
    }
    if (a.passes >= 0) s.passes = a.passes;
    if (a.pass_photons > 0) s.pass_photons = a.pass_photons;
    if (a.initial_radius > 0) s.initial_radius = a.initial_radius;
    if (s.passes == 0 && s.time == 0) {
        std::cerr << "lenslab: error: --passes 0 means no pass limit, which needs a time budget (--time)\n";
        return 2;
    }

    const int threads = a.threads > 0 ? a.threads : tbb::info::default_concurrency();
    const bool progressive = integrator_info(s.integrator).progressive;
    std::string amount = std::to_string(s.spp) + " spp";
    if (progressive) {
        amount = s.passes > 0 ? std::to_string(s.passes) + " passes" : "";
        if (s.time > 0) amount += (amount.empty() ? "" : " or ") + format_seconds(s.time);
    }
    const std::string label = "rendering " + std::to_string(s.width) + "x" + std::to_string(s.height) + ", " +
                              s.integrator + ", " + amount + ", " + std::to_string(threads) + " thread" +
                              (threads > 1 ? "s" : "") + ":";
    ProgressPrinter printer(label);
    RenderControl control(a.quiet ? RenderControl::ProgressFn{} : RenderControl::ProgressFn{std::ref(printer)});
    g_control = &control;
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
    if (!result.stats.summary.empty() && !a.quiet) std::fprintf(stderr, "%s\n", result.stats.summary.c_str());
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
        std::printf("wrote %s (%dx%d, %d passes, %.2f s)\n", a.output.c_str(), s.width, s.height, result.stats.passes,
                    result.seconds);
    } else {
        std::printf("wrote %s (%dx%d, %d spp, %.2f s)\n", a.output.c_str(), s.width, s.height, s.spp,
                    result.seconds);
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
    cmd->add_option("--width", args->width, "Image width in pixels (overrides the scene)")
        ->check(CLI::TypeValidator<int>())->check(CLI::Range(1, kMaxImageSide));
    cmd->add_option("--height", args->height, "Image height in pixels (overrides the scene)")
        ->check(CLI::TypeValidator<int>())->check(CLI::Range(1, kMaxImageSide));
    cmd->add_option("--spp", args->spp, "Samples per pixel (overrides the scene)")
        ->check(CLI::TypeValidator<int>())->check(CLI::Range(1, kMaxSpp));
    cmd->add_option("--max-depth", args->max_depth, "Longest specular chain (overrides the scene)")
        ->check(CLI::TypeValidator<int>())->check(CLI::Range(0, kMaxDepth));
    cmd->add_option("--seed", args->seed, "Random seed (overrides the scene)")
        ->check(CLI::TypeValidator<int64_t>())->check(CLI::Range(int64_t{0}, int64_t{2147483647}));
    cmd->add_option("--threads", args->threads, "Worker threads (default: all cores)")
        ->check(CLI::TypeValidator<int>())->check(CLI::Range(1, 1024));
    cmd->add_option("--exposure", args->exposure, "Exposure in stops applied before writing")
        ->capture_default_str()->check(CLI::Range(-64.0, 64.0));
    cmd->add_flag("-q,--quiet", args->quiet, "No progress on stderr");
    cmd->add_option("--integrator", args->integrator, "whitted, photon_map, sppm or path (overrides the scene)")
        ->check(CLI::IsMember(kIntegratorNames));
    cmd->add_option("--photons", args->photons, "Photons emitted per light (photon_map)")
        ->check(CLI::TypeValidator<int64_t>())->check(CLI::Range(int64_t{1}, kMaxPhotonsPerLight));
    cmd->add_option("--caustic-photons", args->caustic_photons,
                    "Photons aimed at the glass and mirrors, per light (photon_map; sppm: per pass)")
        ->check(CLI::TypeValidator<int64_t>())->check(CLI::Range(int64_t{1}, kMaxPhotonsPerLight));
    cmd->add_option("--aim-photons", args->aim_photons,
                    "on: aim caustic photons at the glass and mirrors (default); off: emit all uniformly")
        ->check(CLI::IsMember({"on", "off"}));
    cmd->add_option("--radius", args->radius, "Photon gather radius (photon_map)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--filter", args->filter, "Photon filter: cone, gaussian or box")
        ->check(CLI::IsMember(kPhotonFilterNames));
    cmd->add_option("--direct", args->direct, "Direct light from shadow_rays or the photon_map")
        ->check(CLI::IsMember(kDirectLightNames));
    cmd->add_option("--filter-k", args->filter_k, "Cone filter constant k >= 1")
        ->check(CLI::Range(1.0, 1e9));
    cmd->add_option("--max-photons-per-estimate", args->max_photons_per_estimate,
                    "Cap on the photons one radiance estimate gathers")
        ->check(CLI::TypeValidator<int>())->check(CLI::Range(1, 1000000));
    cmd->add_option("--passes", args->passes, "sppm: passes to run (0: no limit, needs --time)")
        ->check(CLI::TypeValidator<int>())->check(CLI::Range(0, 1 << 24));
    cmd->add_option("--time", args->time, "sppm: time budget in seconds (passes run until it is spent)")
        ->check(CLI::Range(0.0, 1e9));
    cmd->add_option("--pass-photons", args->pass_photons, "sppm: photons emitted per light in each pass")
        ->check(CLI::TypeValidator<int64_t>())->check(CLI::Range(int64_t{1}, int64_t{1} << 30));
    cmd->add_option("--initial-radius", args->initial_radius, "sppm: initial gather radius (default: auto)")
        ->check(CLI::PositiveNumber);
    return [args] { return run(*args); };
}

}  // namespace lenslab::cli
