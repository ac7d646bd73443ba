// `lenslab sweep SCENE --set POINTER=FROM:TO:COUNT -o DIR`: one scene per value of a swept
// number, rendered (DIR/frames/NNNNN.png, and an animation) or measured on the optical bench
// with --analyze (DIR/frames/NNNNN.json, DIR/sweep.csv). Frames already written are kept, so
// an interrupted sweep resumes where it stopped.

#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include "analysis/report/analyze_request.h"
#include "analysis/report/sweep_table.h"
#include "analyze_options.h"
#include "cluster/cluster_session.h"
#include "commands.h"
#include "render_image.h"
#include "scene/json_reader.h"
#include "scene/scene_json.h"
#include "scene/sweep_plan.h"
#include "sweep_animation.h"
#include "util/atomic_file.h"
#include "util/output_path.h"

namespace lenslab::cli {

namespace {

struct SweepArgs {
    std::string scene;
    std::vector<std::string> sets;
    std::string output;
    bool analyze = false;
    std::string animation;
    int fps = 10;
    std::string ffmpeg;
    bool overwrite = false;
    RenderImageOptions image;
    AnalyzeRequest request;
    CLI::App* render_options = nullptr;
    CLI::App* bench_options = nullptr;
};

int sweep_usage_error(const std::string& message) {
    std::cerr << "lenslab: error: " << message << "\n";
    return 2;
}

// The first option of `group` given on the command line, if any.
const CLI::Option* first_given(const CLI::App& group) {
    for (const CLI::Option* option : group.get_options()) {
        if (option->count() > 0) return option;
    }
    return nullptr;
}

// What the options say against each other, before any work.
std::optional<std::string> sweep_option_error(const SweepArgs& a) {
    if (const CLI::Option* o = a.analyze ? first_given(*a.render_options) : nullptr) {
        return o->get_name() + ": an option of rendered frames, and --analyze renders none";
    }
    if (const CLI::Option* o = a.analyze ? nullptr : first_given(*a.bench_options)) {
        return o->get_name() + ": an option of the optical bench, which needs --analyze";
    }
    if (!a.animation.empty() && a.analyze) {
        return "--animation: --analyze writes figures, not images to animate";
    }
    if (!a.animation.empty() && !is_animation_path(a.animation)) {
        return "--animation '" + a.animation +
               "': unknown kind of animation (use a .gif or .mp4 "
               "file name)";
    }
    if (a.analyze) return figure_option_error(with_implied_tables(a.request));
    return std::nullopt;
}

// "(/objects/1/center/2 = 0.5)": what frame `frame` sets.
std::string frame_values_text(const SweepPlan& plan, int frame) {
    std::string text;
    for (const SweepParameter& p : plan.parameters) {
        text += std::string(text.empty() ? "(" : ", ") + p.pointer + " = " +
                format_number(sweep_value(p, frame));
    }
    return text + ")";
}

// "frame 3/10 (/objects/1/center/2 = 0.5)", counted from 1 as a person counts; the files
// count from 0 (frame 3/10 is frames/00002.png).
std::string frame_label(const SweepPlan& plan, int frame) {
    return "frame " + std::to_string(frame + 1) + "/" + std::to_string(plan.count) + " " +
           frame_values_text(plan, frame);
}

std::string frame_file(const SweepArgs& a, int frame) {
    const std::string extension = a.analyze ? ".json" : ".png";
    return (std::filesystem::path(a.output) / "frames" / (frame_stem(frame) + extension)).string();
}

bool file_exists(const std::string& path) {
    std::error_code ec;
    return std::filesystem::is_regular_file(path, ec);
}

nlohmann::ordered_json read_frame_report(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    try {
        return nlohmann::ordered_json::parse(text.str());
    } catch (const nlohmann::json::exception&) {
        throw Error(file +
                    ": not a frame of sweep --analyze (unreadable JSON); remove it, or "
                    "run again with --overwrite");
    }
}

// Frame `frame`'s scene, read by the scene reader; its errors name the frame and its values.
Scene frame_scene(const SweepArgs& a, const SweepPlan& plan, const nlohmann::json& base,
                  int frame) {
    const nlohmann::json root = sweep_frame_json(base, plan, frame);
    try {
        if (a.analyze)
            return scene_from_file_json(root, a.scene,
                                        {.require_camera = false, .build_for_rendering = false});
        return a.image.overrides->scene_from(root, a.scene);
    } catch (const SceneError& e) {
        throw Error(frame_label(plan, frame) + ": " + e.what());
    }
}

// Frame `frame` rendered or measured into its file. False when the render was cancelled
// (Ctrl-C).
bool sweep_frame(const SweepArgs& a, const SweepPlan& plan, const nlohmann::json& base, int frame) {
    const Scene scene = frame_scene(a, plan, base, frame);
    const std::string file = frame_file(a, frame);
    if (!a.analyze) return render_image(scene, a.image, file) == RenderImageOutcome::Written;
    try {
        write_text_atomically(file, analyze_report(scene, a.request, a.scene).dump(2) + "\n");
    } catch (const AnalyzeRequestError& e) {
        throw AnalyzeRequestError(frame_label(plan, frame) + ": " + e.what());
    } catch (const SceneError& e) {
        throw Error(frame_label(plan, frame) + ": " + e.what());
    }
    std::printf("wrote %s\n", file.c_str());
    return true;
}

// On rank 0, once every frame is written: sweep.json, and sweep.csv or the animation.
void assemble_sweep(const SweepArgs& a, const SweepPlan& plan) {
    std::vector<std::string> files;
    std::vector<nlohmann::ordered_json> reports;
    for (int frame = 0; frame < plan.count; ++frame) {
        files.push_back(frame_file(a, frame));
        if (!file_exists(files.back()))
            throw Error(files.back() + ": missing, so the sweep cannot be assembled");
        if (a.analyze) reports.push_back(read_frame_report(files.back()));
    }
    const std::filesystem::path dir(a.output);
    std::vector<std::string> relative;
    for (int frame = 0; frame < plan.count; ++frame)
        relative.push_back("frames/" + std::filesystem::path(files[frame]).filename().string());
    const std::string summary = (dir / "sweep.json").string();
    write_text_atomically(summary,
                          sweep_summary_json(plan, a.scene, relative, reports).dump(2) + "\n");
    if (a.analyze) {
        const std::string csv = (dir / "sweep.csv").string();
        write_text_atomically(csv, sweep_csv(plan, reports));
        std::printf("wrote %s and %s (%d frames)\n", csv.c_str(), summary.c_str(), plan.count);
    } else {
        std::printf("wrote %s (%d frames)\n", summary.c_str(), plan.count);
    }
    if (!a.animation.empty()) {
        const std::string pattern = (dir / "frames" / "%05d.png").string();
        assemble_animation(find_ffmpeg(a.ffmpeg), pattern, plan.count, a.fps, a.animation);
        std::printf("wrote %s (%d frames at %d fps)\n", a.animation.c_str(), plan.count, a.fps);
    }
}

int run(const SweepArgs& a) {
    // Under mpirun or srun the ranks share the frames, each rendering its own ones alone.
    Communicator& world = world_communicator();
    const int rank = world.rank(), size = world.size();

    SweepPlan plan;
    try {
        plan = parse_sweep_plan(a.sets);
    } catch (const SweepError& e) {
        return sweep_usage_error(e.what());
    }
    if (const auto error = sweep_option_error(a)) return sweep_usage_error(*error);
    // Before any work: an unwritable folder or animation, or no ffmpeg, fails at once.
    const std::string frames_dir = (std::filesystem::path(a.output) / "frames").string();
    check_output_directory(frames_dir);
    if (!a.animation.empty()) (void)find_ffmpeg(a.ffmpeg);
    nlohmann::json base;
    if (a.analyze) {
        base = read_scene_json_file(a.scene);
    } else {
        base = a.image.overrides->patched_json(a.scene);
        if (const auto error = unbounded_passes_error(*a.image.overrides, base))
            return sweep_usage_error(*error);
    }
    check_sweep_targets(base, plan);
    // A linear range's values lie between its ends, and the reader's bounds are ranges, so
    // reading the two end frames' scenes finds nearly every bad range before any work.
    (void)frame_scene(a, plan, base, 0);
    if (plan.count > 1) (void)frame_scene(a, plan, base, plan.count - 1);
    if (rank == 0) create_output_directory(frames_dir);
    world.barrier();                                           // the folder is there for every rank
    if (!a.animation.empty()) check_output_file(a.animation);  // it may go into the new folder

    std::vector<int> todo;
    const std::vector<int> mine = frames_for_rank(plan.count, rank, size);
    for (int frame : mine) {
        if (a.overwrite || !file_exists(frame_file(a, frame))) todo.push_back(frame);
    }
    if (todo.size() < mine.size()) {
        std::printf("skipped %zu of %zu frames already in %s (--overwrite %s them again)\n",
                    mine.size() - todo.size(), mine.size(), frames_dir.c_str(),
                    a.analyze ? "measures" : "renders");
    }
    for (int frame : todo) {
        if (!a.image.quiet) std::fprintf(stderr, "%s\n", frame_label(plan, frame).c_str());
        std::fflush(stdout);
        try {
            if (!sweep_frame(a, plan, base, frame)) {
                std::cerr << "lenslab: sweep stopped at " << frame_label(plan, frame)
                          << "; run it again to resume\n";
                return 130;
            }
        } catch (const AnalyzeRequestError& e) {
            return sweep_usage_error(e.what());
        }
    }
    // Rank 0 assembles from the frame files, all of them: it waits for the others' first.
    world.barrier();
    if (rank == 0) assemble_sweep(a, plan);
    return 0;
}

}  // namespace

Action add_sweep_command(CLI::App& app) {
    auto args = std::make_shared<SweepArgs>();
    CLI::App* cmd = app.add_subcommand(
        "sweep",
        "Render or measure one scene per value of a swept number: frames, an animation, a CSV");
    cmd->add_option("scene", args->scene, "Scene file (JSON)")->required();
    cmd->add_option("--set", args->sets,
                    "The swept number: a JSON pointer into the scene and a linear range, both "
                    "ends included (e.g. /objects/1/center/2=0:5:10); repeat to sweep several "
                    "together (the same COUNT each)")
        ->type_name("POINTER=FROM:TO:COUNT")
        ->allow_extra_args(false)
        ->required();
    cmd->add_option("-o,--output", args->output,
                    "Folder of the sweep: frames/NNNNN.png (or .json), sweep.json, sweep.csv")
        ->required();
    cmd->add_flag("--analyze", args->analyze,
                  "Measure each frame on the optical bench (lenslab analyze --json) instead of "
                  "rendering it: frames/NNNNN.json and sweep.csv");
    cmd->add_option("--animation", args->animation,
                    "Assemble the rendered frames into this animation, .gif or .mp4 (with ffmpeg)");
    cmd->add_option("--fps", args->fps, "Frames per second of --animation (default 10)")
        ->check(whole_number<int>())
        ->check(CLI::Range(1, 240));
    cmd->add_option("--ffmpeg", args->ffmpeg,
                    "The ffmpeg program for --animation (default: ffmpeg on PATH)");
    cmd->add_flag("--overwrite", args->overwrite,
                  "Render (or measure) every frame again, even those already in the folder");
    args->render_options =
        cmd->add_option_group("Rendered frames", "As lenslab render; not with --analyze");
    add_render_image_options(*args->render_options, args->image);
    // --quiet serves --analyze too, so it belongs to the sweep itself.
    args->render_options->remove_option(args->render_options->get_option("--quiet"));
    cmd->add_flag("-q,--quiet", args->image.quiet, "No progress on stderr");
    args->bench_options =
        cmd->add_option_group("Optical bench", "With --analyze; as lenslab analyze");
    add_analyze_options(*args->bench_options, args->request);
    // A file per figure would be overwritten frame after frame (--unit only labels them), and
    // the table is not printed.
    for (const char* name : {"--json", "--svg", "--spots-svg", "--fans-svg", "--curves-svg",
                             "--focal-shift-svg", "--mtf-svg", "--seidel", "--unit"}) {
        args->bench_options->remove_option(args->bench_options->get_option(name));
    }
    cmd->get_option("--fps")->needs(cmd->get_option("--animation"));
    cmd->get_option("--ffmpeg")->needs(cmd->get_option("--animation"));
    return [args] { return run(*args); };
}

}  // namespace lenslab::cli
