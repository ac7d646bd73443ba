#include "render/memory_budget.h"

#include <unistd.h>

#include <fstream>
#include <limits>

namespace lenslab {

uint64_t available_memory_bytes() {
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    uint64_t kib = 0;
    while (meminfo >> key >> kib) {
        if (key == "MemAvailable:") return kib * 1024;
        meminfo.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
    }
    return static_cast<uint64_t>(sysconf(_SC_PHYS_PAGES)) *
           static_cast<uint64_t>(sysconf(_SC_PAGE_SIZE));
}

void check_memory_budget(uint64_t need, const std::string& needs, const std::string& detail,
                         const std::string& advice) {
    const uint64_t have = available_memory_bytes();
    if (need <= have / 10 * 8) return;
    throw ResourceError(needs + " " + std::to_string(need >> 20) + " MiB" + detail + ", but only " +
                        std::to_string(have >> 20) + " MiB of memory is available; " + advice);
}

}  // namespace lenslab
