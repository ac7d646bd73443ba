#include "scene/limits.h"

#include <filesystem>

#include "scene/json_reader.h"

namespace lenslab {

std::optional<std::string> image_size_problem(int64_t width, int64_t height) {
    if (width * height <= kMaxImagePixels) return std::nullopt;
    return std::to_string(width) + " x " + std::to_string(height) + " is " +
           std::to_string(width * height) + " pixels, more than the " +
           std::to_string(kMaxImagePixels) + " (8192 x 8192) allowed";
}

void check_count(size_t count, size_t limit, const std::string& path, const std::string& what) {
    if (count <= limit) return;
    throw SceneError(path, "holds " + std::to_string(count) + " " + what + ", more than the " +
                               std::to_string(limit) + " allowed");
}

namespace {

std::string mebibytes(uint64_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

}  // namespace

std::optional<std::string> file_read_problem(const std::string& path, uint64_t limit) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status)) return std::nullopt;
    if (fs::is_directory(status)) return "is a directory";
    if (!fs::is_regular_file(status)) return "is not a regular file (a device or a pipe)";
    const uint64_t size = fs::file_size(path, ec);
    if (!ec && size > limit) {
        return "is " + mebibytes(size) + " (" + std::to_string(size) + " bytes), more than the " +
               mebibytes(limit) + " allowed";
    }
    return std::nullopt;
}

}  // namespace lenslab
