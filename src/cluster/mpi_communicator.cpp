#include "cluster/mpi_communicator.h"

// The C API only: Open MPI's mpi.h otherwise pulls in its C++ bindings (removed in MPI-3).
#ifndef OMPI_SKIP_MPICXX
#define OMPI_SKIP_MPICXX 1
#endif
#include <mpi.h>

#include <climits>
#include <cstdint>
#include <string>

#include "util/error.h"

namespace lenslab {

namespace {

int message_bytes(size_t n) {
    if (n > static_cast<size_t>(INT_MAX))
        throw Error("cluster: a message of " + std::to_string(n) +
                    " bytes is over MPI's 2 GiB limit (use fewer photons per pass or more ranks)");
    return static_cast<int>(n);
}

// Displacements of `counts` laid end to end, and the whole length.
std::vector<int> displacements(const std::vector<int>& counts, size_t& total) {
    std::vector<int> at(counts.size());
    total = 0;
    for (size_t r = 0; r < counts.size(); ++r) {
        at[r] = message_bytes(total);
        total += static_cast<size_t>(counts[r]);
    }
    message_bytes(total);
    return at;
}

std::vector<Bytes> split_by_rank(const Bytes& all, const std::vector<int>& counts,
                                 const std::vector<int>& at) {
    std::vector<Bytes> out(counts.size());
    for (size_t r = 0; r < counts.size(); ++r)
        out[r].assign(all.begin() + at[r], all.begin() + at[r] + counts[r]);
    return out;
}

}  // namespace

MpiCommunicator::MpiCommunicator() {
    MPI_Comm_rank(MPI_COMM_WORLD, &m_rank);
    MPI_Comm_size(MPI_COMM_WORLD, &m_size);
}

void MpiCommunicator::barrier() { MPI_Barrier(MPI_COMM_WORLD); }

std::vector<Bytes> MpiCommunicator::all_gather(std::span<const std::byte> mine) {
    const int count = message_bytes(mine.size());
    std::vector<int> counts(static_cast<size_t>(m_size));
    MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
    size_t total = 0;
    const std::vector<int> at = displacements(counts, total);
    Bytes all(total);
    MPI_Allgatherv(mine.data(), count, MPI_BYTE, all.data(), counts.data(), at.data(), MPI_BYTE,
                   MPI_COMM_WORLD);
    return split_by_rank(all, counts, at);
}

std::vector<Bytes> MpiCommunicator::gather_to_root(std::span<const std::byte> mine) {
    const int count = message_bytes(mine.size());
    std::vector<int> counts(static_cast<size_t>(m_size));
    MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    size_t total = 0;
    const std::vector<int> at = m_rank == 0 ? displacements(counts, total) : std::vector<int>{};
    Bytes all(total);
    MPI_Gatherv(mine.data(), count, MPI_BYTE, all.data(), counts.data(), at.data(), MPI_BYTE, 0,
                MPI_COMM_WORLD);
    return m_rank == 0 ? split_by_rank(all, counts, at) : std::vector<Bytes>{};
}

void MpiCommunicator::broadcast(Bytes& bytes) {
    uint64_t n = bytes.size();
    MPI_Bcast(&n, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    bytes.resize(static_cast<size_t>(n));
    MPI_Bcast(bytes.data(), message_bytes(bytes.size()), MPI_BYTE, 0, MPI_COMM_WORLD);
}

}  // namespace lenslab
