#include "render_image.h"

#include <tbb/info.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <functional>
#include <iostream>

#include "commands.h"
#include "image/image_io.h"
#include "interrupt_cancels.h"
#include "render/render_session.h"
#include "scene/render_settings.h"
#include "scene/render_tone_map.h"

namespace lenslab::cli {

namespace {

std::string format_seconds(double s) {
    char text[32];
    std::snprintf(text, sizeof text, "%g s", s);
    return text;
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

}  // namespace

void add_render_image_options(CLI::App& cmd, RenderImageOptions& options) {
    cmd.add_option("--threads", options.threads, "Worker threads (default: all cores)")
        ->check(whole_number<int>())
        ->check(CLI::Range(1, 1024));
    cmd.add_option("--exposure", options.exposure, "Exposure in stops applied before writing")
        ->capture_default_str()
        ->check(CLI::Range(-64.0, 64.0));
    cmd.add_flag("-q,--quiet", options.quiet, "No progress on stderr");
    // --width ... --initial-radius: generated from the render block's declaration.
    options.overrides = std::make_shared<RenderOverrides>(cmd);
}

std::optional<std::string> unbounded_passes_error(const RenderOverrides& overrides,
                                                  const nlohmann::json& root) {
    if (!overrides.given("passes") && !overrides.given("time")) return std::nullopt;
    const nlohmann::json& r = root["render"];
    const RenderSettings d;
    const auto number = [&r](const char* key, double fallback) {
        return r.is_object() && r.contains(key) && r[key].is_number() ? r[key].get<double>()
                                                                      : fallback;
    };
    if (number("passes", d.passes) != 0 || number("time", d.time) != 0) return std::nullopt;
    return "--passes 0 means no pass limit, which needs a time budget (--time)";
}

namespace {

// Points where a heterogeneous medium's density left [0, bound] (medium_density.h): each
// a small bias, and a sign that the bound was estimated too low.
uint64_t density_points_clamped(const Scene& scene) {
    uint64_t n = 0;
    if (scene.atmosphere && scene.atmosphere->density)
        n += scene.atmosphere->density->points_clamped();
    for (const SceneObject& o : scene.objects)
        if (o.medium && o.medium->density) n += o.medium->density->points_clamped();
    return n;
}

}  // namespace

RenderImageOutcome render_image(const Scene& scene, const RenderImageOptions& options,
                                const std::string& output, Communicator& cluster) {
    const RenderSettings& s = scene.render;
    const int threads = options.threads > 0 ? options.threads : tbb::info::default_concurrency();
    const bool progressive = integrator_info(s.integrator).progressive;
    std::string amount = std::to_string(s.spp) + " spp";
    if (progressive) {
        amount = s.passes > 0 ? std::to_string(s.passes) + " passes" : "";
        if (s.time > 0) amount += (amount.empty() ? "" : " or ") + format_seconds(s.time);
    }
    const std::string label =
        "rendering " + std::to_string(s.width) + "x" + std::to_string(s.height) + ", " +
        s.integrator + ", " + amount + ", " + std::to_string(threads) + " thread" +
        (threads > 1 ? "s" : "") +
        (cluster.size() > 1 ? " x " + std::to_string(cluster.size()) + " ranks" : "") + ":";
    ProgressPrinter printer(label);
    RenderControl control(options.quiet ? RenderControl::ProgressFn{}
                                        : RenderControl::ProgressFn{std::ref(printer)});
    control.set_cluster(cluster);
    InterruptCancels interrupts(control);
    const RenderResult result = render_scene(scene, control, threads);
    if (result.cancelled) {
        interrupts.release();
        std::cerr << "\nlenslab: render cancelled; nothing written\n";
        return RenderImageOutcome::Cancelled;
    }
    if (!cluster.is_root()) {
        interrupts.release();
        return RenderImageOutcome::Written;  // by the root
    }
    if (!result.stats.summary.empty() && !options.quiet)
        std::fprintf(stderr, "%s\n", result.stats.summary.c_str());
    if (control.non_finite_samples() > 0) {
        std::fprintf(stderr,
                     "lenslab: warning: %lld samples came out NaN or infinite and were left out of "
                     "their pixels (a bug in lenslab; please report it with the scene)\n",
                     static_cast<long long>(control.non_finite_samples()));
    }
    if (const uint64_t clamped = density_points_clamped(scene)) {
        std::fprintf(stderr,
                     "lenslab: warning: a medium's density exceeded its bound at %llu points "
                     "met while rendering, and was clamped there (give a larger density_max)\n",
                     static_cast<unsigned long long>(clamped));
    }
    // The file is written atomically; holding Ctrl-C (and kill's SIGTERM) back until it is
    // in place also leaves no temporary file behind. One that came meanwhile ends the
    // process right after.
    sigset_t held, previous;
    sigemptyset(&held);
    sigaddset(&held, SIGINT);
    sigaddset(&held, SIGTERM);
    sigprocmask(SIG_BLOCK, &held, &previous);
    interrupts.release();
    try {
        write_image(result.film, output, tone_map_for(scene.render, options.exposure));
    } catch (...) {
        sigprocmask(SIG_SETMASK, &previous, nullptr);
        throw;
    }
    sigprocmask(SIG_SETMASK, &previous, nullptr);
    if (result.stats.passes > 0) {
        std::printf("wrote %s (%dx%d, %d passes, %.2f s)\n", output.c_str(), s.width, s.height,
                    result.stats.passes, result.seconds);
    } else {
        std::printf("wrote %s (%dx%d, %d spp, %.2f s)\n", output.c_str(), s.width, s.height, s.spp,
                    result.seconds);
    }
    return RenderImageOutcome::Written;
}

}  // namespace lenslab::cli
