#pragma once
// Files written whole or not at all. The content goes to a temporary file in the same folder
// (so the rename cannot cross file systems), which is renamed over the target only once it
// is complete: an interrupted or failed write never leaves a half file under the real name,
// and an existing file stays as it was until the new one replaces it.

#include <functional>
#include <string>

#include "util/error.h"

namespace lenslab {

class FileWriteError : public Error {
public:
    using Error::Error;
};

// The temporary name write_atomically uses for `path`: "<path>.tmp<pid><extension>" (the
// extension kept for libraries that look at it; the pid keeps two processes apart).
std::string temporary_path_for(const std::string& path);

// Calls `write(temporary)` to fill the temporary file, then renames it to `path`. If `write`
// throws, or the rename fails, the temporary is removed and the exception (a FileWriteError
// for the rename) propagates.
void write_atomically(const std::string& path,
                      const std::function<void(const std::string&)>& write);

// `text` written atomically. Throws FileWriteError.
void write_text_atomically(const std::string& path, const std::string& text);

}  // namespace lenslab
