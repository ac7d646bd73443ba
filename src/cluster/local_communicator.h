#pragma once
// A job of one process: every exchange returns the caller's own data.

#include "cluster/communicator.h"

namespace lenslab {

class LocalCommunicator final : public Communicator {
public:
    int rank() const override { return 0; }
    int size() const override { return 1; }
    void barrier() override {}
    std::vector<Bytes> all_gather(std::span<const std::byte> mine) override;
    std::vector<Bytes> gather_to_root(std::span<const std::byte> mine) override;
    void broadcast(Bytes&) override {}
};

}  // namespace lenslab
