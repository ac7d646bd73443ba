// `lenslab analyze SCENE` (or a lens file, .zmx, .zar or .seq): the optical bench. Focal
// lengths, principal planes, spherical and chromatic aberration and spot sizes of the lenses
// on one axis, as a table or JSON, and a ray diagram as SVG. The measuring is the library's
// (analysis/report/analyze_request.h); this command reads the options and prints.

#include <filesystem>
#include <iostream>
#include <memory>

#include "analysis/report/analyze_request.h"
#include "analysis/report/curve_report.h"
#include "analysis/report/diffraction_report.h"
#include "analysis/report/fan_report.h"
#include "analysis/report/field_map_report.h"
#include "analysis/report/spot_report.h"
#include "analysis/report/wavefront_report.h"
#include "analyze_options.h"
#include "commands.h"
#include "lensfile/lens_file.h"
#include "scene/json_reader.h"
#include "scene/scene_json.h"
#include "util/output_path.h"

namespace lenslab::cli {

namespace {

struct AnalyzeArgs {
    std::string scene;
    AnalyzeRequest request;
};

int analyze_usage_error(const std::string& message) {
    std::cerr << "lenslab: error: " << message << "\n";
    return 2;
}

int run(const AnalyzeArgs& args) {
    const AnalyzeRequest a = with_implied_tables(args.request);
    // Before the analysis, so a bad path costs nothing.
    for (const std::string* file :
         {&a.svg, &a.spots_svg, &a.fans_svg, &a.curves_svg, &a.focal_shift_svg, &a.mtf_svg}) {
        if (!file->empty()) check_output_file(*file);
    }
    if (const auto error = figure_option_error(a)) return analyze_usage_error(*error);
    const SceneReadOptions read{.require_camera = false, .build_for_rendering = false};
    // A lens file stands for a scene holding it alone, along +z, with its own bench data.
    const Scene scene =
        is_lens_file_path(args.scene)
            ? scene_from_json({{"objects",
                                {{{"type", "lens_file"},
                                  {"file", std::filesystem::absolute(args.scene).string()},
                                  {"vertex", {0, 0, 0}},
                                  {"axis", {0, 0, 1}}}}}},
                              "", read)
            : load_scene_file(args.scene, read);
    AnalyzeResults results;
    try {
        results = analyze_scene(scene, a, args.scene);
    } catch (const AnalyzeRequestError& e) {
        return analyze_usage_error(e.what());
    }
    if (a.json) {
        std::cout << analyze_json(results, a, args.scene).dump(2) << "\n";
        return 0;
    }
    const OpticalSystem& system = results.system;
    std::cout << "lenslab analyze " << args.scene << ": "
              << report_table(system, results.report, a.seidel);
    if (!results.from_lens_file.empty()) {
        std::cout << "\nFrom the lens file's bench data (options given here win):";
        for (const std::string& key : results.from_lens_file) std::cout << " " << key;
        std::cout << "\n";
    }
    for (const std::string& why : results.not_from_lens_file)
        std::cout << "Not taken from the lens file: " << why << "\n";
    if (results.diffraction) {
        const FieldMtfs* mtf = results.field_mtf ? &*results.field_mtf : nullptr;
        std::cout << diffraction_table(*results.diffraction, a.psf ? &results.field_psf : nullptr,
                                       mtf);
    }
    if (results.through_focus) std::cout << through_focus_table(*results.through_focus);
    if (results.wavefronts) std::cout << wavefront_table(*results.wavefronts);
    if (results.spots) std::cout << spots_table(system, *results.spots);
    if (results.field_map) std::cout << field_map_table(system, *results.field_map);
    if (results.fans) std::cout << fans_table(system, *results.fans);
    if (results.opd_fans) std::cout << fans_table(system, *results.opd_fans, FanQuantity::Opd);
    if (results.curves) std::cout << field_curves_table(system, *results.curves);
    if (results.shift) std::cout << focal_shift_table(*results.shift);
    if (!a.svg.empty()) std::cout << "\nray diagram written to " << a.svg << "\n";
    // The figures written, and what the table's last lines call them.
    const struct {
        const std::string& file;
        const char* name;
    } figures[] = {{a.spots_svg, "spot diagrams"},
                   {a.fans_svg, "ray fans"},
                   {a.curves_svg, "field curves"},
                   {a.focal_shift_svg, "focal shift"},
                   {a.mtf_svg, "MTF"}};
    for (const auto& figure : figures) {
        if (!figure.file.empty()) std::cout << figure.name << " written to " << figure.file << "\n";
    }
    return 0;
}

}  // namespace

Action add_analyze_command(CLI::App& app) {
    auto args = std::make_shared<AnalyzeArgs>();
    CLI::App* cmd = app.add_subcommand(
        "analyze",
        "Optical bench: focal lengths, aberrations and a ray diagram of the lenses on one axis");
    cmd->add_option("scene", args->scene,
                    "Scene file (JSON; a camera is not needed), or a lens file (.zmx, .zar, "
                    ".seq) alone")
        ->required();
    add_analyze_options(*cmd, args->request);
    return [args] { return run(*args); };
}

}  // namespace lenslab::cli
