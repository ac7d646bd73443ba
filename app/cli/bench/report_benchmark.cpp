#include "bench/report_benchmark.h"

#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <sstream>

#include "render/camera.h"
#include "render/integrator_names.h"
#include "render/integrators/photon_map.h"

namespace lenslab {

namespace {

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Box-filters `film` down to size x size and pastes it at (x0, y0) of `grid`.
void paste_thumbnail(const Film& film, Film& grid, int x0, int y0, int size) {
    for (int ty = 0; ty < size; ++ty) {
        for (int tx = 0; tx < size; ++tx) {
            const int xa = tx * film.width() / size,
                      xb = std::max(xa + 1, (tx + 1) * film.width() / size);
            const int ya = ty * film.height() / size,
                      yb = std::max(ya + 1, (ty + 1) * film.height() / size);
            Rgb sum;
            for (int y = ya; y < yb; ++y) {
                for (int x = xa; x < xb; ++x) {
                    const PixelRgb& p = film.at(x, y);
                    sum += Rgb{p.r, p.g, p.b};
                }
            }
            grid.set(x0 + tx, y0 + ty, sum * (1.0 / ((xb - xa) * (yb - ya))));
        }
    }
}

}  // namespace

double report_build_seconds(int64_t photons) {
    static const std::map<int64_t, double> table{
        {100000, 1.794}, {350000, 6.722}, {600000, 11.948}, {850000, 17.718}, {1100000, 23.214}};
    const auto it = table.find(photons);
    return it == table.end() ? 0.0 : it->second;
}

double report_render_seconds(int64_t photons, double radius) {
    static const std::map<std::pair<int, int64_t>, double> table{
        {{25, 100000}, 9.264},    {{25, 350000}, 16.019},   {{25, 600000}, 20.838},
        {{25, 850000}, 25.420},   {{25, 1100000}, 29.201},  {{50, 100000}, 12.602},
        {{50, 350000}, 25.423},   {{50, 600000}, 36.297},   {{50, 850000}, 44.543},
        {{50, 1100000}, 55.177},  {{75, 100000}, 16.722},   {{75, 350000}, 37.342},
        {{75, 600000}, 56.473},   {{75, 850000}, 73.379},   {{75, 1100000}, 89.379},
        {{100, 100000}, 22.153},  {{100, 350000}, 53.549},  {{100, 600000}, 83.571},
        {{100, 850000}, 110.001}, {{100, 1100000}, 135.275}};
    const int key = static_cast<int>(std::lround(radius * 1000));
    if (std::abs(radius * 1000 - key) > 1e-6) return 0.0;
    const auto it = table.find({key, photons});
    return it == table.end() ? 0.0 : it->second;
}

ReportBenchmarkResult run_report_benchmark(const Scene& base, const ReportBenchmarkSettings& s,
                                           const std::function<void(const std::string&)>& log) {
    Scene scene = base;
    scene.render.width = s.width;
    scene.render.height = s.height;
    scene.render.spp = s.spp;
    scene.render.integrator = integrators::kPhotonMap;
    scene.render.direct = DirectLight::PhotonMap;
    const Camera camera(scene.camera, s.width, s.height);

    ReportBenchmarkResult result;
    const int columns = static_cast<int>(s.photons.size()), rows = static_cast<int>(s.radii.size());
    result.grid = Film(columns * s.thumbnail, rows * s.thumbnail);
    tbb::task_arena arena(s.threads > 0 ? s.threads : tbb::task_arena::automatic);
    char line[256];

    for (int c = 0; c < columns; ++c) {
        scene.render.photons = s.photons[c];
        RenderControl control;
        std::vector<double> trace, build;
        std::shared_ptr<const PhotonMap> map;
        PhotonTracingStats stats;
        for (int rep = 0; rep < s.repeats; ++rep) {
            map.reset();  // free the previous maps before tracing new ones
            arena.execute([&] {
                map = std::make_shared<const PhotonMap>(
                    trace_photons(scene, photon_tracing_settings(scene), control, &stats));
            });
            trace.push_back(stats.trace_seconds);
            build.push_back(stats.build_seconds);
        }
        ReportBuildTiming bt{s.photons[c], median(trace), median(build),
                             stats.direct + stats.caustic};
        result.builds.push_back(bt);
        std::snprintf(line, sizeof line,
                      "photons %8lld: traced in %.3f s, maps built in %.3f s (report: %.3f s)",
                      static_cast<long long>(bt.photons), bt.trace_seconds, bt.build_seconds,
                      report_build_seconds(bt.photons));
        log(line);

        for (int r = 0; r < rows; ++r) {
            scene.render.radius = s.radii[r];
            PhotonMapIntegrator integrator(scene);
            integrator.set_photon_map(map);
            Film film(s.width, s.height);
            std::vector<double> times;
            for (int rep = 0; rep < s.repeats; ++rep) {
                const auto t = std::chrono::steady_clock::now();
                arena.execute([&] { integrator.render(scene, camera, film, control); });
                times.push_back(seconds_since(t));
            }
            ReportRenderTiming rt{s.photons[c], s.radii[r], median(times)};
            result.renders.push_back(rt);
            std::snprintf(line, sizeof line,
                          "photons %8lld, radius %.3f: rendered in %.3f s (report: %.3f s)",
                          static_cast<long long>(rt.photons), rt.radius, rt.render_seconds,
                          report_render_seconds(rt.photons, rt.radius));
            log(line);
            paste_thumbnail(film, result.grid, c * s.thumbnail, r * s.thumbnail, s.thumbnail);
        }
    }
    return result;
}

std::string report_benchmark_csv(const ReportBenchmarkResult& r) {
    std::ostringstream csv;
    csv << "photons,radius,trace_s,build_s,render_s,total_s,report_build_s,report_render_s,"
           "build_ratio,render_ratio\n";
    for (const ReportRenderTiming& rt : r.renders) {
        const auto b =
            std::find_if(r.builds.begin(), r.builds.end(),
                         [&](const ReportBuildTiming& x) { return x.photons == rt.photons; });
        const double build = b->trace_seconds + b->build_seconds;
        const double rb = report_build_seconds(rt.photons),
                     rr = report_render_seconds(rt.photons, rt.radius);
        char row[256];
        std::snprintf(row, sizeof row, "%lld,%.3f,%.4f,%.4f,%.4f,%.4f,%.3f,%.3f,%.4f,%.4f\n",
                      static_cast<long long>(rt.photons), rt.radius, b->trace_seconds,
                      b->build_seconds, rt.render_seconds, build + rt.render_seconds, rb, rr,
                      rb > 0 ? build / rb : 0.0, rr > 0 ? rt.render_seconds / rr : 0.0);
        csv << row;
    }
    return csv.str();
}

}  // namespace lenslab
