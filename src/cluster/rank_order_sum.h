#pragma once
// Sums over ranks that come out the same on every run: rank 0 adds the ranks' arrays in rank
// order 0, 1, ..., N-1 and sends the result back. (MPI_Allreduce leaves the order of a
// floating-point sum to the library, so its last bits may change from run to run.)

#include <cstdint>
#include <span>

#include "cluster/communicator.h"

namespace lenslab {

// On return every rank holds the element-wise sum of all ranks' `values` (same lengths).
void sum_in_rank_order(Communicator& comm, std::span<double> values);
void sum_in_rank_order(Communicator& comm, std::span<uint64_t> values);

}  // namespace lenslab
