#pragma once
// The course report's cost experiment (its Tables 4.1 and 4.2, Figures 4.2 to 4.4): photon
// map build time against photons per light, and render time against gather radius, at
// 900x900 on the default scene. `lenslab bench report` runs it and writes the results.

#include <functional>
#include <string>
#include <vector>

#include "image/film.h"
#include "scene/scene.h"

namespace lenslab {

struct ReportBenchmarkSettings {
    std::vector<int64_t> photons{100000, 350000, 600000, 850000, 1100000};
    std::vector<double> radii{0.025, 0.05, 0.075, 0.1};
    int width = 900, height = 900, spp = 1;
    int repeats = 3;      // each timing is the median of this many runs
    int threads = 0;      // 0: all cores
    int thumbnail = 180;  // pixel size of each image in the grid
};

struct ReportBuildTiming {
    int64_t photons = 0;
    double trace_seconds = 0, build_seconds = 0;  // medians
    size_t stored = 0;
};

struct ReportRenderTiming {
    int64_t photons = 0;
    double radius = 0;
    double render_seconds = 0;  // median; the pixels only, maps already built
};

struct ReportBenchmarkResult {
    std::vector<ReportBuildTiming> builds;
    std::vector<ReportRenderTiming> renders;
    Film grid;  // rows: radii, columns: photon counts (the report's Figure 4.4)
};

// The course report's figures (docs/performance.md lists them), for the ratios in the CSV.
double report_build_seconds(int64_t photons);                  // Table 4.1; 0 if not listed
double report_render_seconds(int64_t photons, double radius);  // Table 4.2; 0 if not listed

// Runs the experiment on `scene` with the photon-map integrator (direct light from the
// direct photon map, as the report did). `log` receives one line per measurement.
ReportBenchmarkResult run_report_benchmark(const Scene& scene, const ReportBenchmarkSettings& s,
                                           const std::function<void(const std::string&)>& log);

// CSV with one row per (photons, radius): build and render times and the report's figures.
std::string report_benchmark_csv(const ReportBenchmarkResult& r);

}  // namespace lenslab
