#pragma once
// Where an output may go, checked before any work is done: a command that measures for
// minutes must not learn only at the end that its folder is missing or its file read-only.
// The same rules decide how write_atomically (util/atomic_file.h) writes:
//
// - A symbolic link is written through: the file it points to is replaced, the link stays.
// - An existing regular file must be writable and keeps its permission bits. "Writable"
//   means at least one write bit set and, when not root, access(W_OK); root bypasses the
//   bits, so for root a file with no write bit at all (chmod 444) counts as read-only.
// - A character device or FIFO (/dev/null, /dev/stdout, a pipe) is written in place, every
//   write and the close checked; /dev/full reports "No space left on device".
// - A directory, or any other kind of file, is refused.
// - A new file needs a folder that exists and that we may write into.

#include <sys/types.h>

#include <string>

#include "util/file_write_error.h"

namespace lenslab {

struct OutputTarget {
    enum class Kind { NewFile, RegularFile, Stream };
    std::string path;  // the file actually written: symbolic links followed
    Kind kind = Kind::NewFile;
    mode_t mode = 0;  // an existing file's permission bits, kept on its replacement
    uid_t owner = 0;
    gid_t group = 0;
};

// The file `path` names, its symbolic links followed, checked as above. Throws FileWriteError
// "cannot write 'PATH': REASON" naming `path` as given.
OutputTarget check_output_file(const std::string& path);

// A folder for outputs: an existing directory we may write into, or a path whose nearest
// existing ancestor is one (the folder is created by create_output_directory). Throws
// FileWriteError "cannot write into folder 'PATH': REASON".
void check_output_directory(const std::string& path);

// check_output_directory, then creates the folder and its parents if they are missing.
void create_output_directory(const std::string& path);

// strerror's text as the end of a lenslab message: "no space left on device".
std::string error_reason(int error);

// "cannot write 'PATH': REASON", the one wording of every output error.
FileWriteError output_error(const std::string& path, const std::string& reason);

}  // namespace lenslab
