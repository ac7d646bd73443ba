#include "sweep_animation.h"

#include <filesystem>
#include <vector>

#include "child_process.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace lenslab::cli {

namespace {

bool has_extension(const std::string& path, const std::string& extension) {
    return std::filesystem::path(path).extension() == extension &&
           std::filesystem::path(path).stem() != "";
}

// ffmpeg's output, cut to its last lines: the reason is at the end.
std::string ffmpeg_tail(const std::string& output) {
    const size_t keep = 600;
    std::string tail = output.size() > keep ? "..." + output.substr(output.size() - keep) : output;
    while (!tail.empty() && (tail.back() == '\n' || tail.back() == '\r')) tail.pop_back();
    return tail;
}

}  // namespace

bool is_animation_path(const std::string& path) {
    return has_extension(path, ".gif") || has_extension(path, ".mp4");
}

std::string find_ffmpeg(const std::string& program) {
    if (!program.empty()) {
        if (!is_executable_file(program))
            throw Error("--ffmpeg '" + program + "': not an executable file");
        return program;
    }
    const std::string found = find_on_path("ffmpeg");
    if (found.empty()) {
        throw Error(
            "--animation needs ffmpeg, which is not on PATH (Debian: apt install ffmpeg; or "
            "name it with --ffmpeg)");
    }
    return found;
}

void assemble_animation(const std::string& ffmpeg, const std::string& frames, int count, int fps,
                        const std::string& output) {
    const bool gif = has_extension(output, ".gif");
    // A GIF gets a palette made from its own frames; H.264 wants even sizes and 4:2:0 colour
    // for players to show it.
    const std::string filter =
        gif ? "split[a][b];[a]palettegen[p];[b][p]paletteuse" : "pad=ceil(iw/2)*2:ceil(ih/2)*2";
    write_atomically(output, [&](const std::string& temporary) {
        // -frames:v: a longer earlier sweep's frames may follow ours in the folder.
        std::vector<std::string> argv = {ffmpeg, "-hide_banner", "-loglevel", "error", "-y"};
        argv.insert(argv.end(), {"-framerate", std::to_string(fps), "-start_number", "0", "-i",
                                 frames, "-vf", filter, "-frames:v", std::to_string(count)});
        const std::vector<std::string> encoder =
            gif ? std::vector<std::string>{"-f", "gif"}
                : std::vector<std::string>{"-c:v", "libx264", "-pix_fmt", "yuv420p", "-f", "mp4"};
        argv.insert(argv.end(), encoder.begin(), encoder.end());
        argv.push_back(temporary);
        const std::filesystem::path log = temporary + ".log";
        const ChildResult r = run_child(argv, std::filesystem::current_path(), log);
        if (!r.exited || r.exit_code != 0) {
            const std::string how = !r.exited ? "was killed"
                                    : r.exit_code == 127
                                        ? "could not be started"
                                        : "failed (exit code " + std::to_string(r.exit_code) + ")";
            const std::string said = ffmpeg_tail(r.output);
            throw Error("--animation " + output + ": " + ffmpeg + " " + how +
                        (said.empty() ? "" : ": " + said) +
                        "\n  command: " + shell_command_line(argv));
        }
    });
}

}  // namespace lenslab::cli
