#include "util/output_path.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace lenslab {

namespace fs = std::filesystem;

namespace {

FileWriteError folder_error(const std::string& path, const std::string& reason) {
    return FileWriteError("cannot write into folder '" + path + "': " + reason);
}

// `path` with the symbolic links of its last component followed, dangling or not: a new file
// is created where a dangling link points, as a shell's `>` would.
fs::path follow_links(const std::string& path) {
    fs::path p = path;
    for (int hops = 0; hops < 40; ++hops) {  // Linux's own limit
        struct stat st {};
        if (lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p;
        std::error_code ec;
        const fs::path target = fs::read_symlink(p, ec);
        if (ec) throw output_error(path, error_reason(ec.value()));
        p = target.is_absolute() ? target : p.parent_path() / target;
    }
    throw output_error(path, error_reason(ELOOP));
}

// The folder a file `file` is created in: it must exist and let us add and rename files.
void check_folder_of(const std::string& path, const fs::path& file) {
    const fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
    struct stat st {};
    if (stat(folder.c_str(), &st) != 0) {
        throw output_error(path, errno == ENOENT
                                     ? "folder '" + folder.string() + "' does not exist"
                                     : "folder '" + folder.string() + "': " + error_reason(errno));
    }
    if (!S_ISDIR(st.st_mode)) throw output_error(path, "'" + folder.string() + "' is not a folder");
    if (faccessat(AT_FDCWD, folder.c_str(), W_OK | X_OK, AT_EACCESS) != 0)
        throw output_error(path, "folder '" + folder.string() + "': " + error_reason(errno));
}

// Root passes access(W_OK) whatever the bits, so the bits decide for root: a file with no
// write bit at all was made read-only on purpose and is not replaced.
void check_file_writable(const std::string& path, const fs::path& file, mode_t mode) {
    if ((mode & 0222) == 0) throw output_error(path, "the file is read-only");
    if (faccessat(AT_FDCWD, file.c_str(), W_OK, AT_EACCESS) != 0)
        throw output_error(path, error_reason(errno));
}

}  // namespace

std::string error_reason(int error) {
    std::string text = std::strerror(error);
    if (!text.empty() && text[0] >= 'A' && text[0] <= 'Z') text[0] = char(text[0] - 'A' + 'a');
    return text;
}

FileWriteError output_error(const std::string& path, const std::string& reason) {
    return FileWriteError("cannot write '" + path + "': " + reason);
}

OutputTarget check_output_file(const std::string& path) {
    if (path.empty()) throw output_error(path, "no file name");
    OutputTarget target;
    struct stat st {};
    if (stat(path.c_str(), &st) != 0) {
        if (errno != ENOENT) throw output_error(path, error_reason(errno));
        target.path = follow_links(path).string();
        check_folder_of(path, target.path);
        return target;
    }
    if (S_ISDIR(st.st_mode)) throw output_error(path, "is a directory");
    if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) {
        // Written in place through `path` as given: the kernel follows its links, including
        // the ones no path names (/dev/stdout to a pipe).
        if (faccessat(AT_FDCWD, path.c_str(), W_OK, AT_EACCESS) != 0)
            throw output_error(path, error_reason(errno));
        target.path = path;
        target.kind = OutputTarget::Kind::Stream;
        return target;
    }
    if (!S_ISREG(st.st_mode))
        throw output_error(path, "is neither a regular file nor a character device");
    const fs::path file = follow_links(path);
    check_file_writable(path, file, st.st_mode);
    check_folder_of(path, file);
    target.path = file.string();
    target.kind = OutputTarget::Kind::RegularFile;
    target.mode = st.st_mode & 0777;
    target.owner = st.st_uid;
    target.group = st.st_gid;
    return target;
}

void check_output_directory(const std::string& path) {
    if (path.empty()) throw folder_error(path, "no folder name");
    struct stat st {};
    fs::path existing = path;
    // A folder still to be created: its nearest existing ancestor decides.
    while (stat(existing.c_str(), &st) != 0) {
        if (errno != ENOENT || existing == ".") throw folder_error(path, error_reason(errno));
        existing = existing.has_parent_path() ? existing.parent_path() : fs::path(".");
    }
    if (!S_ISDIR(st.st_mode)) {
        throw folder_error(path, existing == path ? "is not a directory"
                                                  : "'" + existing.string() + "' is not a folder");
    }
    if (faccessat(AT_FDCWD, existing.c_str(), W_OK | X_OK, AT_EACCESS) != 0)
        throw folder_error(path, error_reason(errno));
}

void create_output_directory(const std::string& path) {
    check_output_directory(path);
    std::error_code ec;
    fs::create_directories(path, ec);
    if (ec) throw folder_error(path, error_reason(ec.value()));
}

}  // namespace lenslab
