#pragma once
// Files written whole or not at all. The content goes to a temporary file in the same folder
// (so the rename cannot cross file systems), which is renamed over the target only once it
// is complete: an interrupted or failed write never leaves a half file under the real name,
// and an existing file stays as it was until the new one replaces it.
//
// The target is checked first and written by the rules of util/output_path.h: through
// symbolic links, keeping an existing file's permission bits, never over a read-only file or
// a directory; a character device or FIFO, which cannot be replaced, is written in place.

#include <functional>
#include <string>
#include <string_view>

#include "util/file_write_error.h"
#include "util/output_path.h"

namespace lenslab {

// A fresh temporary name in the folder of `path`: ".lenslab-<pid>-<n>.tmp<extension>". Its
// length does not grow with the target's name (a 250-character name leaves no room for a
// suffix within NAME_MAX); the extension is kept, when short, for programs such as POV-Ray
// that add their own to a name without one. The pid keeps two processes apart, the counter
// two writes of one process.
std::string temporary_path_for(const std::string& path);

// Calls `write(temporary)` to fill a temporary file, then renames it over `path` (its links
// followed). If `write` throws, or the rename fails, the temporary is removed and the
// exception (a FileWriteError for the rename) propagates. For a character device or FIFO the
// temporary is made in the system's temporary folder and copied to the device.
void write_atomically(const std::string& path,
                      const std::function<void(const std::string&)>& write);

// `text` written atomically. Throws FileWriteError.
void write_text_atomically(const std::string& path, const std::string& text);

// `data` written to `file` (created or truncated), every write and the close checked: a full
// disk is reported as "cannot write 'NAME': no space left on device". `name` is the path the
// message names.
void write_whole_file(const std::string& file, std::string_view data, const std::string& name);

}  // namespace lenslab
