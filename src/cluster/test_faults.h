#pragma once
// Faults on purpose, for the tests of a job that loses a rank (tests/cluster/mpi_run.sh):
// LENSLAB_TEST_KILL_RANK=<rank> makes that rank die (_exit(9), as a crash or the OOM killer
// would) and LENSLAB_TEST_FAIL_RANK=<rank> makes it throw an Error, both at its first
// exchange of render data, i.e. mid-render. Only in jobs of more than one rank.

#include "cluster/communicator.h"

namespace lenslab {

void cluster_fault_point(const Communicator& comm);

}  // namespace lenslab
