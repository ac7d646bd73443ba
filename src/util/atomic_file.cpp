#include "util/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace lenslab {

std::string temporary_path_for(const std::string& path) {
    return path + ".tmp" + std::to_string(getpid()) +
           std::filesystem::path(path).extension().string();
}

void write_atomically(const std::string& path,
                      const std::function<void(const std::string&)>& write) {
    const std::string tmp = temporary_path_for(path);
    std::error_code ec;
    try {
        write(tmp);
    } catch (...) {
        std::filesystem::remove(tmp, ec);
        throw;
    }
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::error_code ignored;
        std::filesystem::remove(tmp, ignored);
        throw FileWriteError("cannot write '" + path + "': " + ec.message());
    }
}

void write_text_atomically(const std::string& path, const std::string& text) {
    write_atomically(path, [&](const std::string& tmp) {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw FileWriteError("cannot write '" + path + "': " + std::strerror(errno));
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
        out.close();
        if (!out) throw FileWriteError("cannot write '" + path + "': write failed (disk full?)");
    });
}

}  // namespace lenslab
