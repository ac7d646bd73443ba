#pragma once
// The largest scene lenslab accepts, checked while the scene is read and again before a
// render starts (docs/reliability.md tables each limit with its message). Far above any real
// scene, they turn a typo like "width": 1e9 or a runaway generated file into one clear
// refusal instead of an exhausted memory, a crash or a render that never ends.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace lenslab {

inline constexpr int kMaxImageSide = 16384;                       // render.width, render.height
inline constexpr int64_t kMaxImagePixels = int64_t{1} << 26;      // width x height (8192 x 8192)
inline constexpr int kMaxSpp = 1 << 20;                           // render.spp
inline constexpr int kMaxDepth = 1000;                            // render.max_depth
inline constexpr int kMaxDispersionSamples = 256;                 // render.dispersion_samples
inline constexpr int64_t kMaxPhotonsPerLight = int64_t{1} << 40;  // also checked against memory
inline constexpr size_t kMaxObjects = 1000000;                    // objects[]
inline constexpr size_t kMaxLights = 10000;                       // lights[]
inline constexpr size_t kMaxMeshTriangles = 10000000;             // per mesh, after triangulation
inline constexpr uint64_t kMaxSceneFileBytes = uint64_t{256} << 20;  // a scene file
inline constexpr uint64_t kMaxObjFileBytes = uint64_t{512} << 20;    // an OBJ file

// Why a width x height image is refused ("16384 x 16384 is 268435456 pixels, more than the
// 67108864 (8192 x 8192) allowed"), or nullopt. The sides are checked separately.
std::optional<std::string> image_size_problem(int64_t width, int64_t height);

// Throws SceneError(path, "holds COUNT WHAT, more than the LIMIT allowed") when count > limit.
void check_count(size_t count, size_t limit, const std::string& path, const std::string& what);

// Why the file at `path` may not be read, checked before opening it: "is a directory", "is
// not a regular file (a device or a pipe)" (reading /dev/zero would never end), or "is 300
// MiB (...), more than the 256 MiB allowed" when it exceeds `limit` bytes. nullopt when it may
// be read, or does not exist (opening it then says so).
std::optional<std::string> file_read_problem(const std::string& path, uint64_t limit);

}  // namespace lenslab
