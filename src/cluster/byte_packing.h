#pragma once
// Plain values to and from the byte messages of a Communicator (same machine types on every
// rank, as MPI jobs of one program have).

#include <cstring>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "cluster/communicator.h"

namespace lenslab {

template <class T>
void append_bytes(Bytes& out, std::span<const T> values) {
    static_assert(std::is_trivially_copyable_v<T>, "sent as bytes");
    const size_t at = out.size();
    out.resize(at + values.size_bytes());
    if (!values.empty()) std::memcpy(out.data() + at, values.data(), values.size_bytes());
}

template <class T>
void append_value(Bytes& out, const T& value) {
    append_bytes(out, std::span<const T>(&value, 1));
}

// Reads values off the front of a message, in the order they were appended.
class ByteReader {
public:
    explicit ByteReader(const Bytes& bytes) : m_bytes(bytes) {}

    template <class T>
    void read_into(std::span<T> values) {
        static_assert(std::is_trivially_copyable_v<T>, "sent as bytes");
        if (m_at + values.size_bytes() > m_bytes.size())
            throw std::logic_error("cluster: a message shorter than its contents");
        if (!values.empty()) std::memcpy(values.data(), m_bytes.data() + m_at, values.size_bytes());
        m_at += values.size_bytes();
    }

    template <class T>
    T value() {
        T v{};
        read_into(std::span<T>(&v, 1));
        return v;
    }

private:
    const Bytes& m_bytes;
    size_t m_at = 0;
};

// Rank 0's `value` on every rank.
template <class T>
void broadcast_value(Communicator& comm, T& value) {
    if (comm.alone()) return;
    Bytes bytes;
    if (comm.is_root()) append_value(bytes, value);
    comm.broadcast(bytes);
    ByteReader(bytes).read_into(std::span<T>(&value, 1));
}

}  // namespace lenslab
