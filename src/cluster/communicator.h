#pragma once
// The processes of one job and what they exchange: lenslab's whole use of MPI, behind one
// interface so the renderers never see MPI and the build without it stays the same. Every
// call is collective: all ranks make the same calls in the same order, from the thread that
// started the job (MPI is initialised for that alone).

#include <cstddef>
#include <span>
#include <vector>

namespace lenslab {

using Bytes = std::vector<std::byte>;

class Communicator {
public:
    virtual ~Communicator() = default;

    virtual int rank() const = 0;
    virtual int size() const = 0;
    bool is_root() const { return rank() == 0; }
    bool alone() const { return size() == 1; }

    virtual void barrier() = 0;
    // Every rank's `mine` (sizes may differ), indexed by rank, on every rank.
    virtual std::vector<Bytes> all_gather(std::span<const std::byte> mine) = 0;
    // Every rank's `mine`, indexed by rank, on rank 0; an empty list on the others.
    virtual std::vector<Bytes> gather_to_root(std::span<const std::byte> mine) = 0;
    // Rank 0's `bytes` on every rank (resized to fit).
    virtual void broadcast(Bytes& bytes) = 0;
};

// The communicator of a process that works alone (size 1): what renders use unless told
// otherwise, and the whole world when lenslab was not started by mpirun or srun.
Communicator& this_process_alone();

}  // namespace lenslab
