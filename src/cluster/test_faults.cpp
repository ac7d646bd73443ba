#include "cluster/test_faults.h"

#include <unistd.h>

#include <cstdlib>
#include <string>

#include "util/error.h"

namespace lenslab {

namespace {

bool names_rank(const char* variable, int rank) {
    const char* value = std::getenv(variable);
    return value && *value && std::string(value) == std::to_string(rank);
}

}  // namespace

void cluster_fault_point(const Communicator& comm) {
    if (comm.alone()) return;
    if (names_rank("LENSLAB_TEST_KILL_RANK", comm.rank())) _exit(9);
    if (names_rank("LENSLAB_TEST_FAIL_RANK", comm.rank()))
        throw Error("rank " + std::to_string(comm.rank()) +
                    " failed on purpose (LENSLAB_TEST_FAIL_RANK)");
}

}  // namespace lenslab
