// `lenslab trace SCENE --origin x,y,z --direction x,y,z`: print the tree of a ray's paths.

#include <iostream>
#include <memory>
#include <regex>

#include "analysis/trace/ray_tree.h"
#include "commands.h"
#include "scene/scene_json.h"

namespace lenslab::cli {

namespace {

struct TraceArgs {
    std::string scene;
    std::vector<double> origin, direction;
    RayTreeOptions options;
};

int run(const TraceArgs& a) {
    const Vec3 d{a.direction[0], a.direction[1], a.direction[2]};
    const Vec3 o{a.origin[0], a.origin[1], a.origin[2]};
    if (!(length(d) > 0)) {
        std::cerr << "lenslab: error: --direction: must be a non-zero vector\n";
        return 2;
    }
    const Scene scene = load_scene_file(a.scene);
    const Ray ray{o, normalize(d)};
    const RayTree tree = trace_ray_tree(scene, ray, a.options);
    // Points and directions on one line each, so a tree reads segment by segment.
    static const std::regex triple(R"(\[\s*([^,\[\]\s]+),\s*([^,\[\]\s]+),\s*([^,\[\]\s]+)\s*\])");
    std::cout << std::regex_replace(to_json(scene, tree).dump(2), triple, "[$1, $2, $3]") << "\n";
    return 0;
}

}  // namespace

Action add_trace_command(CLI::App& app) {
    auto args = std::make_shared<TraceArgs>();
    CLI::App* cmd =
        app.add_subcommand("trace", "Trace one ray and print the tree of its paths as JSON");
    cmd->add_option("scene", args->scene, "Scene file (JSON)")->required();
    cmd->add_option("--origin", args->origin, "Ray origin x,y,z")
        ->required()
        ->delimiter(',')
        ->expected(3);
    cmd->add_option("--direction", args->direction, "Ray direction x,y,z (need not be unit length)")
        ->required()
        ->delimiter(',')
        ->expected(3);
    cmd->add_option("--max-depth", args->options.max_depth,
                    "Specular bounces followed along any one path")
        ->check(whole_number<int>())
        ->check(CLI::Range(0, 1000))
        ->capture_default_str();
    cmd->add_option("--min-weight", args->options.min_weight,
                    "Branches carrying less of the ray's power are dropped")
        ->check(CLI::Range(kMinBranchWeight, 1.0))
        ->capture_default_str();
    cmd->add_option(
           "-w,--wavelength", args->options.wavelength_nm,
           "Wavelength in nm (in air; in vacuum for a scene with \"ambient\": \"vacuum\") for "
           "dispersive materials (default: the d line)")
        ->check(CLI::Range(kLambdaMinNm, 2500.0))
        ->capture_default_str();
    return [args] { return run(*args); };
}

}  // namespace lenslab::cli
