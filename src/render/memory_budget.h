#pragma once
// The one check that a render's large allocations (photon storage, a pass's photons, the
// film) fit in memory, made before the work starts so an oversized request is refused with
// a clear message instead of ending in an out-of-memory kill.

#include <cstdint>
#include <string>

#include "util/error.h"

namespace lenslab {

// Thrown before any work when what was asked for cannot fit in memory.
class ResourceError : public Error {
public:
    using Error::Error;
};

// Memory free now: /proc/meminfo's MemAvailable, else the physical memory.
uint64_t available_memory_bytes();

// Refuses `need` bytes beyond 80% of the memory available (the rest is left for the image,
// the scene and the system) by throwing ResourceError with the message
//   "<needs> <need> MiB<detail>, but only <have> MiB of memory is available; <advice>"
// e.g. needs "image: 9000 x 9000 needs", detail "", advice "render a smaller image".
void check_memory_budget(uint64_t need, const std::string& needs, const std::string& detail,
                         const std::string& advice);

}  // namespace lenslab
