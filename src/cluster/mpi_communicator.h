#pragma once
// The ranks of MPI_COMM_WORLD (compiled only when lenslab is built with MPI). Messages are
// bytes; each may hold up to 2 GiB (MPI's int counts).

#include "cluster/communicator.h"

namespace lenslab {

class MpiCommunicator final : public Communicator {
public:
    MpiCommunicator();  // MPI must be initialised
    int rank() const override { return m_rank; }
    int size() const override { return m_size; }
    void barrier() override;
    std::vector<Bytes> all_gather(std::span<const std::byte> mine) override;
    std::vector<Bytes> gather_to_root(std::span<const std::byte> mine) override;
    void broadcast(Bytes& bytes) override;

private:
    int m_rank = 0, m_size = 1;
};

}  // namespace lenslab
