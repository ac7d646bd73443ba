#include "util/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace lenslab {

namespace fs = std::filesystem;

namespace {

// A temporary next to `path`, created empty (O_EXCL: never one that is there already) with
// the mode a new file gets, so the writers fill it in place.
std::string create_temporary_for(const std::string& path, const std::string& name) {
    for (int attempt = 0; attempt < 100; ++attempt) {
        const std::string tmp = temporary_path_for(path);
        const int fd = open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            close(fd);
            return tmp;
        }
        if (errno != EEXIST) throw output_error(name, error_reason(errno));
    }
    throw output_error(name, "no free temporary name");
}

std::string read_whole_file(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_all(int fd, std::string_view data, const std::string& name) {
    while (!data.empty()) {
        const ssize_t n = ::write(fd, data.data(), data.size());
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const int error = n < 0 ? errno : ENOSPC;
            close(fd);
            throw output_error(name, error_reason(error));
        }
        data.remove_prefix(static_cast<size_t>(n));
    }
}

// A device or FIFO cannot be replaced: the content is made in a temporary file of the system's
// temporary folder (the writers may seek, which a pipe cannot) and then copied to it.
void write_to_stream(const OutputTarget& target, const std::string& name,
                     const std::function<void(const std::string&)>& write) {
    const std::string tmp =
        create_temporary_for((fs::temp_directory_path() / "lenslab").string(), name);
    try {
        write(tmp);
        const std::string content = read_whole_file(tmp);
        std::error_code ignored;
        fs::remove(tmp, ignored);
        const int fd = open(target.path.c_str(), O_WRONLY | O_CLOEXEC);
        if (fd < 0) throw output_error(name, error_reason(errno));
        write_all(fd, content, name);
        if (close(fd) != 0) throw output_error(name, error_reason(errno));
    } catch (...) {
        std::error_code ignored;
        fs::remove(tmp, ignored);
        throw;
    }
}

// The replacement of an existing file keeps its permission bits and, where we may (root),
// its owner: rewriting a 0600 file must not make it readable by others.
void keep_mode_and_owner(const std::string& tmp, const OutputTarget& target,
                         const std::string& name) {
    if (target.kind != OutputTarget::Kind::RegularFile) return;
    if (chmod(tmp.c_str(), target.mode) != 0) throw output_error(name, error_reason(errno));
    if (geteuid() == 0) {
        [[maybe_unused]] const int ignored = chown(tmp.c_str(), target.owner, target.group);
    }
}

}  // namespace

std::string temporary_path_for(const std::string& path) {
    static std::atomic<unsigned> counter{0};
    std::string extension = fs::path(path).extension().string();
    if (extension.size() > 16) extension.clear();
    const std::string name = ".lenslab-" + std::to_string(getpid()) + "-" +
                             std::to_string(counter.fetch_add(1)) + ".tmp" + extension;
    return (fs::path(path).parent_path() / name).string();
}

void write_atomically(const std::string& path,
                      const std::function<void(const std::string&)>& write) {
    const OutputTarget target = check_output_file(path);
    if (target.kind == OutputTarget::Kind::Stream) {
        write_to_stream(target, path, write);
        return;
    }
    const std::string tmp = create_temporary_for(target.path, path);
    try {
        write(tmp);
        keep_mode_and_owner(tmp, target, path);
    } catch (...) {
        std::error_code ignored;
        fs::remove(tmp, ignored);
        throw;
    }
    std::error_code ec;
    fs::rename(tmp, target.path, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(tmp, ignored);
        throw output_error(path, error_reason(ec.value()));
    }
}

void write_whole_file(const std::string& file, std::string_view data, const std::string& name) {
    const int fd = open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) throw output_error(name, error_reason(errno));
    write_all(fd, data, name);
    if (close(fd) != 0) throw output_error(name, error_reason(errno));
}

void write_text_atomically(const std::string& path, const std::string& text) {
    write_atomically(path, [&](const std::string& tmp) { write_whole_file(tmp, text, path); });
}

}  // namespace lenslab
