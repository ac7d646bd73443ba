#include "bench/sppm_convergence.h"

#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "image/image_io.h"
#include "render/integrator.h"
#include "render/integrator_names.h"
#include "render/integrator_registry.h"
#include "render/progressive_render.h"
#include "render/render_session.h"

namespace lenslab {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

std::string format(const char* fmt, auto... args) {
    char line[256];
    std::snprintf(line, sizeof line, fmt, args...);
    return line;
}

// The path tracer's image of `window` alone: each pixel as a whole render would give it.
Film render_path_window(const Scene& scene, const PixelWindow& window, int threads,
                        double& seconds) {
    Film film(scene.render.width, scene.render.height);
    const Camera camera(scene.camera, scene.render.width, scene.render.height);
    const std::unique_ptr<Integrator> integrator = make_integrator(scene);
    auto* path = dynamic_cast<PixelIntegrator*>(integrator.get());
    RenderControl control;
    const auto t0 = std::chrono::steady_clock::now();
    tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
    arena.execute([&] { path->render_window(scene, camera, film, control, window); });
    seconds = seconds_since(t0);
    return film;
}

}  // namespace

double block_relative_error(const Film& a, const Film& reference, int block) {
    double sum = 0;
    int n = 0;
    for (int y0 = 0; y0 + block <= reference.height(); y0 += block) {
        for (int x0 = 0; x0 + block <= reference.width(); x0 += block) {
            double ma = 0, mr = 0;
            for (int y = y0; y < y0 + block; ++y) {
                for (int x = x0; x < x0 + block; ++x) {
                    ma += luminance(a.at(x, y));
                    mr += luminance(reference.at(x, y));
                }
            }
            if (mr <= 0) continue;
            sum += std::abs(ma - mr) / mr;
            ++n;
        }
    }
    return n ? sum / n : 0.0;
}

double region_relative_error(const Film& a, const Film& reference, const int region[4]) {
    double sum2 = 0, mean = 0;
    int n = 0;
    for (int y = std::max(0, region[1]); y < std::min(reference.height(), region[3]); ++y) {
        for (int x = std::max(0, region[0]); x < std::min(reference.width(), region[2]); ++x) {
            const double d = luminance(a.at(x, y)) - luminance(reference.at(x, y));
            sum2 += d * d;
            mean += luminance(reference.at(x, y));
            ++n;
        }
    }
    return mean > 0 ? std::sqrt(sum2 / n) / (mean / n) : 0.0;
}

double rms_relative_error(const Film& a, const Film& reference) {
    double sum2 = 0, mean = 0;
    const size_t n = reference.pixels().size();
    for (size_t i = 0; i < n; ++i) {
        const double d = luminance(a.pixels()[i]) - luminance(reference.pixels()[i]);
        sum2 += d * d;
        mean += luminance(reference.pixels()[i]);
    }
    mean /= static_cast<double>(n);
    return mean > 0 ? std::sqrt(sum2 / static_cast<double>(n)) / mean : 0.0;
}

ConvergenceResult run_convergence(const Scene& scene, const ConvergenceSettings& s,
                                  const std::function<void(const std::string&)>& log) {
    ConvergenceResult r;
    Scene base = scene;
    base.render.width = s.width;
    base.render.height = s.height;

    // The reference takes a seed of its own, so the images measured share no samples with it.
    Scene ref = base;
    ref.render.integrator = integrators::kPath;
    ref.render.spp = s.reference_spp;
    ref.render.seed = base.render.seed + 1000003;
    RenderControl control;
    if (!s.reference_file.empty()) {
        r.reference = read_exr(s.reference_file);
        if (r.reference.width() != s.width || r.reference.height() != s.height) {
            throw ImageError(format("reference %s is %dx%d, the measurement %dx%d",
                                    s.reference_file.c_str(), r.reference.width(),
                                    r.reference.height(), s.width, s.height));
        }
        log("reference: " + s.reference_file);
    } else {
        RenderResult reference = render_scene(ref, control, s.threads);
        r.reference = std::move(reference.film);
        r.reference_seconds = reference.seconds;
        log(format("reference: path, %d spp, %.2f s", s.reference_spp, r.reference_seconds));
    }
    if (s.has_region() && s.region_spp > 0) {
        Scene region = ref;
        region.render.spp = s.region_spp;
        r.region_reference =
            render_path_window(region, {s.region[0], s.region[1], s.region[2], s.region[3]},
                               s.threads, r.region_reference_seconds);
        log(format("region reference: path, %d spp, %.2f s", s.region_spp,
                   r.region_reference_seconds));
    }
    const Film& region_reference = s.region_spp > 0 ? r.region_reference : r.reference;

    auto add = [&](const std::string& integrator, int amount, double seconds, const Film& film) {
        ConvergencePoint p{
            integrator,
            amount,
            seconds,
            block_relative_error(film, r.reference),
            rms_relative_error(film, r.reference),
            s.has_region() ? region_relative_error(film, region_reference, s.region) : 0.0};
        r.points.push_back(p);
        log(format("%s %d: %.3f s, block error %.4f, rms error %.4f", integrator.c_str(), amount,
                   seconds, p.block_error, p.rms_error) +
            (s.has_region() ? format(", region error %.4f", p.region_error) : std::string()));
    };

    Scene sppm = base;
    sppm.render.integrator = integrators::kSppm;
    ProgressiveRender progressive(sppm, s.threads);
    double seconds = 0;
    std::vector<int> passes = s.passes;
    std::sort(passes.begin(), passes.end());
    for (int target : passes) {
        while (progressive.passes() < target) {
            const auto t0 = std::chrono::steady_clock::now();
            progressive.add_pass(control);
            seconds += seconds_since(t0);
        }
        r.sppm_last = progressive.image();
        add(std::string(integrators::kSppm), target, seconds, r.sppm_last);
    }

    Scene path = base;
    path.render.integrator = integrators::kPath;
    for (int spp : s.path_spp) {
        path.render.spp = spp;
        const RenderResult result = render_scene(path, control, s.threads);
        add(std::string(integrators::kPath), spp, result.seconds, result.film);
    }
    return r;
}

std::string convergence_csv(const ConvergenceResult& r) {
    std::ostringstream out;
    out << "integrator,passes_or_spp,seconds,block_error,rms_error,region_error\n";
    for (const ConvergencePoint& p : r.points) {
        out << p.integrator << "," << p.amount << "," << p.seconds << "," << p.block_error << ","
            << p.rms_error << "," << p.region_error << "\n";
    }
    return out.str();
}

}  // namespace lenslab
