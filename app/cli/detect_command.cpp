// `lenslab detect SCENE -o DIR`: measure the irradiance on every detector in a scene.

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "analysis/detectors/detection_run.h"
#include "analysis/detectors/detector.h"
#include "analysis/detectors/detector_files.h"
#include "cluster/cluster_session.h"
#include "commands.h"
#include "interrupt_cancels.h"
#include "render/photon_tracer.h"
#include "render_overrides.h"
#include "scene/scene_json.h"
#include "util/output_path.h"

namespace lenslab::cli {

namespace {

struct DetectArgs {
    std::string scene;
    std::string output = "detectors";
    int threads = 0;
    bool json = false, quiet = false, log = false;
};

int run(const DetectArgs& a, const RenderOverrides& overrides) {
    const Scene scene = overrides.load(a.scene);
    check_detectable(scene, a.scene);
    // Before the measurement, not after it: the folder, and the files in it if it exists.
    check_output_directory(a.output);
    if (std::filesystem::is_directory(a.output)) {
        for (const std::string& stem : detector_file_stems(scene))
            for (const std::string& file : detector_file_paths(a.output, stem))
                check_output_file(file);
    }
    const DetectionSettings settings = detection_settings(scene, a.threads);

    int last = -1;
    RenderControl control(a.quiet ? RenderControl::ProgressFn{}
                                  : RenderControl::ProgressFn{[&last](double f) {
                                        const int percent = static_cast<int>(f * 100.0);
                                        if (percent / 10 == last / 10) return;
                                        last = percent;
                                        std::fprintf(stderr, "detecting %3d%%\n", percent);
                                    }});
    // Under mpirun or srun the ranks share the photons; rank 0 writes the files.
    Communicator& world = world_communicator();
    control.set_cluster(world);
    InterruptCancels interrupts(control);
    const DetectionResult result = measure_detectors(scene, settings, control);
    interrupts.release();
    if (result.cancelled) {
        std::cerr << "lenslab: detection cancelled; nothing written\n";
        return 130;
    }
    if (!world.is_root()) return 0;

    create_output_directory(a.output);
    const std::vector<std::string> stems = detector_file_stems(result);
    nlohmann::json doc = detection_json(a.scene, settings, result);
    for (size_t i = 0; i < result.detectors.size(); ++i) {
        const DetectorMeasurement& m = result.detectors[i];
        write_detector_files(m, settings, a.output, stems[i],
                             a.log ? ColourScale::Log : ColourScale::Linear);
        const std::string base = (std::filesystem::path(a.output) / stems[i]).string();
        doc["detectors"][i]["files"] = {
            {"csv", base + ".csv"}, {"exr", base + ".exr"}, {"png", base + ".png"}};
        if (!a.json) {
            std::cout << detector_summary_text(m) << "  wrote " << base << ".csv, " << base
                      << ".exr, " << base << ".png\n";
        }
    }
    if (a.json) {
        std::cout << doc.dump(2) << "\n";
    } else {
        std::printf(
            "%lld photons per light, %lld in all (%lld aimed at the glass and mirrors), %.2f s\n",
            static_cast<long long>(settings.photons_per_light),
            static_cast<long long>(result.photons_emitted),
            static_cast<long long>(result.photons_aimed), result.seconds);
    }
    return 0;
}

}  // namespace

Action add_detect_command(CLI::App& app) {
    auto args = std::make_shared<DetectArgs>();
    CLI::App* cmd = app.add_subcommand("detect",
                                       "Measure the irradiance on the scene's detectors (CSV, EXR "
                                       "and false-colour PNG per detector)");
    cmd->add_option("scene", args->scene, "Scene file (JSON) with at least one detector")
        ->required();
    cmd->add_option("-o,--output", args->output, "Folder for <detector>.csv, .exr and .png")
        ->capture_default_str();
    cmd->add_option("--threads", args->threads, "Worker threads (default: all cores)")
        ->check(whole_number<int>())
        ->check(CLI::Range(1, 1024));
    cmd->add_flag("--log", args->log, "Colour the PNG on a log scale (4 decades below the peak)");
    cmd->add_flag("--json", args->json, "Print the summary as JSON");
    cmd->add_flag("-q,--quiet", args->quiet, "No progress on stderr");
    // The render block's keys the photon tracer uses, as `lenslab render` overrides them.
    auto overrides = std::make_shared<RenderOverrides>(
        *cmd,
        std::vector<std::string>{"photons", "caustic_photons", "aim_photons", "seed", "max_depth"});
    return [args, overrides] { return run(*args, *overrides); };
}

}  // namespace lenslab::cli
