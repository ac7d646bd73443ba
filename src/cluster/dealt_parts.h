#pragma once
// Work split across ranks by dealing: item i (a photon chunk, a tile, an image row) belongs
// to rank i mod N, like cards dealt round the table. Each rank computes its own items'
// parts; the exchanges below put the parts together again in item order, so the result is
// the one a single process gets, byte for byte.

#include <cstdint>
#include <span>
#include <vector>

#include "cluster/byte_packing.h"
#include "cluster/communicator.h"
#include "cluster/test_faults.h"

namespace lenslab {

inline bool dealt_to(int64_t item, int rank, int size) { return item % size == rank; }
inline bool dealt_to(int64_t item, const Communicator& comm) {
    return dealt_to(item, comm.rank(), comm.size());
}

namespace detail {

template <class T>
Bytes pack_dealt_parts(const Communicator& comm, const std::vector<std::vector<T>>& parts) {
    Bytes out;
    for (size_t p = static_cast<size_t>(comm.rank()); p < parts.size();
         p += static_cast<size_t>(comm.size())) {
        append_value(out, static_cast<uint64_t>(parts[p].size()));
        append_bytes(out, std::span<const T>(parts[p]));
    }
    return out;
}

// Rank `from`'s parts out of its message, into `parts`.
template <class T>
void unpack_dealt_parts(const Bytes& message, int from, int size,
                        std::vector<std::vector<T>>& parts) {
    ByteReader in(message);
    for (size_t p = static_cast<size_t>(from); p < parts.size(); p += static_cast<size_t>(size)) {
        parts[p].resize(static_cast<size_t>(in.value<uint64_t>()));
        in.read_into(std::span<T>(parts[p]));
    }
}

}  // namespace detail

// Every rank has filled the parts dealt to it; on return every rank has all of them.
template <class T>
void share_dealt_parts(Communicator& comm, std::vector<std::vector<T>>& parts) {
    cluster_fault_point(comm);
    if (comm.alone()) return;
    const std::vector<Bytes> all = comm.all_gather(detail::pack_dealt_parts(comm, parts));
    for (int r = 0; r < comm.size(); ++r)
        if (r != comm.rank()) detail::unpack_dealt_parts(all[size_t(r)], r, comm.size(), parts);
}

// As share_dealt_parts, but only rank 0 ends with all the parts.
template <class T>
void gather_dealt_parts_to_root(Communicator& comm, std::vector<std::vector<T>>& parts) {
    cluster_fault_point(comm);
    if (comm.alone()) return;
    const std::vector<Bytes> all = comm.gather_to_root(detail::pack_dealt_parts(comm, parts));
    for (size_t r = 1; r < all.size(); ++r)
        detail::unpack_dealt_parts(all[r], static_cast<int>(r), comm.size(), parts);
}

}  // namespace lenslab
