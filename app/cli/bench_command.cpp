// `lenslab bench report`: the course report's cost experiment, with its figures beside ours.

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

#include "bench/report_benchmark.h"
#include "bench/sppm_convergence.h"
#include "child_process.h"
#include "commands.h"
#include "image/image_io.h"
#include "render/integrator_names.h"
#include "scene/limits.h"
#include "scene/scene_json.h"
#include "util/atomic_file.h"

namespace lenslab::cli {

namespace {

struct BenchArgs {
    std::string scene;
    std::string out_dir = "bench-report";
    ReportBenchmarkSettings settings;
};

struct ConvergenceArgs {
    std::string scene;
    std::string out_dir = "bench-sppm";
    ConvergenceSettings settings;
    int64_t pass_photons = 0;  // 0: the scene's
    std::string aim_photons;   // "": the scene's
    std::vector<int> region;
};

// Runs gnuplot on `script`, a file in `dir`, with `dir` as its working folder: no shell, and
// the scripts name their files relative to `dir`, so no path is quoted into a command line
// or a script. False when gnuplot is not installed or fails.
bool run_gnuplot(const std::filesystem::path& dir, const std::string& script) {
    const std::string gnuplot = find_on_path("gnuplot");
    if (gnuplot.empty()) return false;
    const ChildResult r = run_child({gnuplot, script}, dir, dir / "gnuplot.log");
    return r.exited && r.exit_code == 0;
}

// Error against time (sppm and path) and sppm's error against passes, log-log.
bool plot_convergence(const std::filesystem::path& dir, const ConvergenceResult& r) {
    std::ostringstream dat;
    for (const std::string_view integrator : {integrators::kSppm, integrators::kPath}) {
        dat << "# " << integrator << ": amount seconds block_error rms_error\n";
        for (const ConvergencePoint& p : r.points) {
            if (p.integrator == integrator)
                dat << p.amount << " " << p.seconds << " " << p.block_error << " " << p.rms_error
                    << "\n";
        }
        dat << "\n\n";
    }
    write_text_atomically((dir / "convergence.dat").string(), dat.str());
    const std::string d = "'convergence.dat'";
    std::ostringstream gp;
    gp << "set terminal pngcairo size 900,600\nset key top right\nset grid\nset logscale xy\n"
          "set ylabel 'error against the path-traced reference'\n"
          "set output 'convergence_time.png'\n"
          "set title 'Error against rendering time (mean over 8x8-pixel blocks of the relative "
          "error)'\n"
          "set xlabel 'seconds'\n"
          "plot "
       << d << " index 0 using 2:3 with linespoints lw 2 title 'sppm (passes)', " << d
       << " index 1 using 2:3 with linespoints lw 2 title 'path (samples per pixel)', " << d
       << " index 0 using 2:4 with linespoints dt 2 lc 1 title 'sppm, RMS per pixel', " << d
       << " index 1 using 2:4 with linespoints dt 2 lc 2 title 'path, RMS per pixel'\n"
          "set output 'convergence_passes.png'\n"
          "set title 'sppm: error against passes'\nset xlabel 'passes'\n"
          "plot "
       << d << " index 0 using 1:3 with linespoints lw 2 title 'mean block error', " << d
       << " index 0 using 1:4 with linespoints lw 2 title 'RMS per pixel'\n";
    write_text_atomically((dir / "convergence.gp").string(), gp.str());
    return run_gnuplot(dir, "convergence.gp");
}

int run_convergence_bench(const ConvergenceArgs& a) {
    Scene scene = a.scene.empty() ? default_scene() : load_scene_file(a.scene);
    if (a.pass_photons > 0) scene.render.pass_photons = a.pass_photons;
    if (!a.aim_photons.empty()) scene.render.aim_photons = a.aim_photons == "on";
    ConvergenceSettings settings = a.settings;
    std::copy(a.region.begin(), a.region.end(), settings.region);
    const std::filesystem::path dir(a.out_dir);
    create_output_directory(a.out_dir);  // before the measurement, not after it
    const ConvergenceResult r = run_convergence(
        scene, settings, [](const std::string& line) { std::cerr << line << "\n"; });
    write_text_atomically((dir / "convergence.csv").string(), convergence_csv(r));
    write_image(r.reference, (dir / "reference.png").string());
    write_image(r.reference, (dir / "reference.exr").string());  // for --reference
    write_image(r.sppm_last, (dir / "sppm.png").string());
    const bool region_apart = r.region_reference.width() > 0;
    if (region_apart) write_image(r.region_reference, (dir / "region_reference.png").string());
    const bool plotted = plot_convergence(dir, r);
    std::printf("wrote %s/convergence.csv, reference.png, reference.exr, %ssppm.png%s\n",
                dir.c_str(), region_apart ? "region_reference.png, " : "",
                plotted ? ", convergence_time.png, convergence_passes.png"
                        : " (install gnuplot for the plots: convergence.gp is written)");
    return 0;
}

// Draws the report's Figures 4.2 (build time) and 4.3 (render time) with gnuplot; returns
// false when gnuplot is not installed (its data and script are written all the same).
bool plot(const std::filesystem::path& dir, const ReportBenchmarkSettings& s,
          const ReportBenchmarkResult& r) {
    // One gnuplot data block per radius: photons, ours (build, render), report's (build, render).
    const auto data = dir / "plot_data.dat";
    std::ostringstream dat;
    for (double radius : s.radii) {
        dat << "# radius " << radius << "\n";
        for (const ReportBuildTiming& b : r.builds) {
            for (const ReportRenderTiming& rt : r.renders) {
                if (rt.photons != b.photons || rt.radius != radius) continue;
                dat << b.photons << " " << b.trace_seconds + b.build_seconds << " "
                    << report_build_seconds(b.photons) << " " << rt.render_seconds << " "
                    << report_render_seconds(b.photons, radius) << "\n";
            }
        }
        dat << "\n\n";
    }
    write_text_atomically(data.string(), dat.str());
    const auto script = dir / "plots.gp";
    const std::string d = "'plot_data.dat'";
    // gnuplot draws into temporary files, renamed into place once it has succeeded.
    const auto build_png = dir / "build_time.png", render_png = dir / "render_time.png";
    const std::string build_tmp = temporary_path_for(build_png.string());
    const std::string render_tmp = temporary_path_for(render_png.string());
    std::ostringstream gp;
    gp << "set terminal pngcairo size 900,600\nset key top left\nset grid\nset logscale y\n"
          "set xlabel 'photons per light'\nset ylabel 'seconds'\n"
          "set output '"
       << std::filesystem::path(build_tmp).filename().string()
       << "'\n"
          "set title 'Photon tracing + map build time (report Table 4.1, Figure 4.2)'\n"
          "plot "
       << d << " index 0 using 1:2 with linespoints lw 2 title 'lenslab', " << d
       << " index 0 using 1:3 with linespoints dt 2 title 'report'\n"
          "set output '"
       << std::filesystem::path(render_tmp).filename().string()
       << "'\n"
          "set title 'Render time against photons per light, per gather radius (report Table 4.2, "
          "Figure 4.3)'\n"
          "plot ";
    for (size_t i = 0; i < s.radii.size(); ++i) {
        gp << (i ? ", " : "") << d << " index " << i << " using 1:4 with linespoints lw 2 lc "
           << i + 1 << " title 'lenslab r=" << s.radii[i] << "', " << d << " index " << i
           << " using 1:5 with linespoints dt 2 lc " << i + 1 << " title 'report r=" << s.radii[i]
           << "'";
    }
    gp << "\nunset output\n";
    write_text_atomically(script.string(), gp.str());
    const bool drawn = run_gnuplot(dir, "plots.gp");
    std::error_code ec;
    if (drawn) {
        std::filesystem::rename(build_tmp, build_png, ec);
        if (!ec) std::filesystem::rename(render_tmp, render_png, ec);
    }
    std::error_code ignored;
    std::filesystem::remove(build_tmp, ignored);
    std::filesystem::remove(render_tmp, ignored);
    return drawn && !ec;
}

int run(const BenchArgs& a) {
    const Scene scene = a.scene.empty() ? default_scene() : load_scene_file(a.scene);
    const std::filesystem::path dir(a.out_dir);
    create_output_directory(a.out_dir);  // before the measurement, not after it
    const ReportBenchmarkResult r = run_report_benchmark(
        scene, a.settings, [](const std::string& line) { std::cerr << line << "\n"; });
    write_text_atomically((dir / "report.csv").string(), report_benchmark_csv(r));
    write_image(r.grid, (dir / "grid.png").string());
    const bool plotted = plot(dir, a.settings, r);
    std::printf("wrote %s/report.csv, %s/grid.png%s\n", dir.c_str(), dir.c_str(),
                plotted ? (", " + (dir / "build_time.png").string() + ", " +
                           (dir / "render_time.png").string())
                              .c_str()
                        : " (install gnuplot for the plots: plots.gp is written)");
    return 0;
}

}  // namespace

Action add_bench_command(CLI::App& app) {
    auto args = std::make_shared<BenchArgs>();
    CLI::App* bench = app.add_subcommand("bench", "Measure lenslab's speed");
    bench->require_subcommand(1);
    CLI::App* report = bench->add_subcommand(
        "report",
        "The course report's experiment: map build and render times against photons and radius");
    report->add_option("scene", args->scene, "Scene file (default: the built-in default scene)");
    report
        ->add_option("-o,--output", args->out_dir, "Folder for report.csv, the plots and grid.png")
        ->capture_default_str();
    ReportBenchmarkSettings& s = args->settings;
    report->add_option("--photons", s.photons, "Photons per light to measure")
        ->delimiter(',')
        ->capture_default_str()
        ->check(whole_number<int64_t>())
        ->check(CLI::Range(int64_t{1}, int64_t{1} << 36));
    report->add_option("--radii", s.radii, "Gather radii to measure")
        ->delimiter(',')
        ->capture_default_str()
        ->check(CLI::PositiveNumber);
    report->add_option("--width", s.width, "Image width")
        ->capture_default_str()
        ->check(whole_number<int>())
        ->check(CLI::Range(1, kMaxImageSide));
    report->add_option("--height", s.height, "Image height")
        ->capture_default_str()
        ->check(whole_number<int>())
        ->check(CLI::Range(1, kMaxImageSide));
    report->add_option("--spp", s.spp, "Samples per pixel")
        ->capture_default_str()
        ->check(whole_number<int>())
        ->check(CLI::Range(1, 1 << 16));
    report->add_option("--repeats", s.repeats, "Runs per timing (the median is kept)")
        ->capture_default_str()
        ->check(whole_number<int>())
        ->check(CLI::Range(1, 100));
    report->add_option("--threads", s.threads, "Worker threads (default: all cores)")
        ->check(whole_number<int>())
        ->check(CLI::Range(1, 1024));

    auto conv = std::make_shared<ConvergenceArgs>();
    // Named after the integrator it measures.
    CLI::App* sppm = bench->add_subcommand(std::string(integrators::kSppm),
                                           "How sppm converges: its error against a long "
                                           "path-traced reference, against passes and time");
    sppm->add_option("scene", conv->scene, "Scene file (default: the built-in default scene)");
    sppm->add_option("-o,--output", conv->out_dir,
                     "Folder for convergence.csv, the plots and images")
        ->capture_default_str();
    ConvergenceSettings& c = conv->settings;
    sppm->add_option("--width", c.width, "Image width")
        ->capture_default_str()
        ->check(whole_number<int>())
        ->check(CLI::Range(8, 16384));
    sppm->add_option("--height", c.height, "Image height")
        ->capture_default_str()
        ->check(whole_number<int>())
        ->check(CLI::Range(8, 16384));
    sppm->add_option("--reference-spp", c.reference_spp,
                     "Samples per pixel of the path-traced reference")
        ->capture_default_str()
        ->check(whole_number<int>())
        ->check(CLI::Range(1, 1 << 24));
    sppm->add_option("--reference", c.reference_file,
                     "An earlier run's reference.exr, measured against instead of rendering "
                     "one (the same scene, width and height)")
        ->check(CLI::ExistingFile);
    sppm->add_option("--passes", c.passes, "sppm pass counts to measure at")
        ->delimiter(',')
        ->capture_default_str()
        ->check(whole_number<int>())
        ->check(CLI::Range(1, 1 << 20));
    sppm->add_option("--path-spp", c.path_spp, "Path-tracing sample counts to compare with")
        ->delimiter(',')
        ->capture_default_str()
        ->check(whole_number<int>())
        ->check(CLI::Range(1, 1 << 20));
    sppm->add_option("--pass-photons", conv->pass_photons,
                     "Photons per light in each sppm pass (default: the scene's)")
        ->check(whole_number<int64_t>())
        ->check(CLI::Range(int64_t{1}, int64_t{1} << 30));
    sppm->add_option("--threads", c.threads, "Worker threads (default: all cores)")
        ->check(whole_number<int>())
        ->check(CLI::Range(1, 1024));
    sppm->add_option("--aim-photons", conv->aim_photons,
                     "on: aim caustic photons at the glass (default: the scene's); off: uniform")
        ->check(CLI::IsMember({"on", "off"}));
    CLI::Option* region =
        sppm->add_option("--region", conv->region,
                         "Also measure the error in the pixels X0,Y0,X1,Y1 (a caustic, say)")
            ->delimiter(',')
            ->expected(4)
            ->check(CLI::Range(0, 16384));
    sppm->add_option("--region-spp", c.region_spp,
                     "Render the region's reference apart at this many samples per pixel "
                     "(default: the reference's)")
        ->check(whole_number<int>())
        ->check(CLI::Range(1, 1 << 24))
        ->needs(region);

    const Action povray = add_bench_povray_command(*bench);
    CLI::App* povray_cmd = bench->get_subcommand("povray");
    const Action optimize = add_bench_optimize_command(*bench);
    CLI::App* optimize_cmd = bench->get_subcommand("optimize");

    // The subcommands share the one action; CLI11 says which was chosen.
    return [args, conv, sppm, povray, povray_cmd, optimize, optimize_cmd] {
        if (sppm->parsed()) return run_convergence_bench(*conv);
        if (povray_cmd->parsed()) return povray();
        if (optimize_cmd->parsed()) return optimize();
        return run(*args);
    };
}

}  // namespace lenslab::cli
