#pragma once
// Running another program as a child process and timing it as a whole, for the benchmarks
// that compare lenslab with other renderers: both sides are measured the same way.

#include <filesystem>
#include <string>
#include <vector>

namespace lenslab::cli {

struct ChildResult {
    bool exited = false;  // false: killed by a signal, or it could not be started
    int exit_code = -1;   // when exited
    double seconds = 0;   // wall time from fork to the end of waitpid
    std::string output;   // stdout and stderr together, in the order written
};

// Runs argv[0] (a path, not looked up on PATH) with `argv`, in folder `workdir`, stdin from
// /dev/null, stdout and stderr both into `log` (overwritten, then read back into `output` and
// removed). Throws std::runtime_error when fork fails; a failed exec shows as exit code 127.
ChildResult run_child(const std::vector<std::string>& argv, const std::filesystem::path& workdir,
                      const std::filesystem::path& log);

// `program` on PATH (the first executable file of that name), or "" when there is none.
std::string find_on_path(const std::string& program);

// True when `path` is a regular file we may execute.
bool is_executable_file(const std::string& path);

// `argv` as one shell command line, quoting what needs it, for showing the commands used.
std::string shell_command_line(const std::vector<std::string>& argv);

}  // namespace lenslab::cli
