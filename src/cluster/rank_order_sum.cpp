#include "cluster/rank_order_sum.h"

#include <stdexcept>

#include "cluster/byte_packing.h"

namespace lenslab {

namespace {

template <class T>
void sum_ranks_in_order(Communicator& comm, std::span<T> values) {
    if (comm.alone()) return;
    Bytes mine;
    append_bytes(mine, std::span<const T>(values));
    const std::vector<Bytes> parts = comm.gather_to_root(mine);
    Bytes total;
    if (comm.is_root()) {
        std::vector<T> sum(values.size()), part(values.size());
        ByteReader(parts[0]).read_into(std::span<T>(sum));
        for (size_t r = 1; r < parts.size(); ++r) {
            if (parts[r].size() != mine.size())
                throw std::logic_error("cluster: ranks summed arrays of different lengths");
            ByteReader(parts[r]).read_into(std::span<T>(part));
            for (size_t i = 0; i < sum.size(); ++i) sum[i] += part[i];
        }
        append_bytes(total, std::span<const T>(sum));
    }
    comm.broadcast(total);
    ByteReader(total).read_into(values);
}

}  // namespace

void sum_in_rank_order(Communicator& comm, std::span<double> values) {
    sum_ranks_in_order(comm, values);
}

void sum_in_rank_order(Communicator& comm, std::span<uint64_t> values) {
    sum_ranks_in_order(comm, values);
}

}  // namespace lenslab
