#pragma once
// What parallel chunks of work deposit (photons), gathered in chunk order so the result does
// not depend on the threads. Each chunk deposits one list for each of kLists kinds (direct and
// caustic photons); list l of every chunk goes to array l. A chunk fills its thread's scratch
// lists, whose pages are faulted in once per thread rather than once per chunk, and hands
// them in: when every earlier chunk is in, they are copied straight to their final place in
// the arrays; otherwise a copy of them waits until the earlier ones arrive. Each photon is so
// written once into memory that is never copied again: a fresh page costs a fault (microseconds in
// a virtual machine), and staging the photons and then joining them in order wrote 38 MB twice for
// the report scene, 0.05 s of its render (docs/performance.md).

#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <map>
#include <memory>
#include <mutex>
#include <type_traits>
#include <utility>
#include <vector>

#include "util/huge_pages.h"

namespace lenslab {

template <class T>
class ChunkCollector {
    static_assert(std::is_trivially_copyable_v<T>, "items are copied as bytes");

public:
    static constexpr size_t kLists = 2;
    using Lists = std::array<std::vector<T>, kLists>;

    // `chunks` chunks, numbered from 0, each list about `capacity` items in all. Only the
    // pages written are faulted in, so a generous capacity costs nothing; past it, the rest
    // of a list is kept apart and joined by take() (slower, never wrong).
    ChunkCollector(size_t chunks, size_t capacity) : m_at(chunks) {
        for (Array& a : m_arrays) {
            a.data = std::make_unique_for_overwrite<T[]>(capacity);
            a.capacity = capacity;
            advise_huge_pages(a.data.get(), capacity * sizeof(T));
        }
    }

    // The calling thread's scratch lists, emptied.
    Lists& scratch() {
        Lists& lists = m_scratch.local();
        for (std::vector<T>& l : lists) l.clear();
        return lists;
    }

    // Hands in chunk `chunk`'s lists (copied; `lists` stays the caller's). Thread-safe; each
    // chunk at most once. The places are given out under a lock, the copies made outside it,
    // so one thread's page faults do not hold up the others.
    void put(size_t chunk, const Lists& lists) {
        std::vector<std::pair<const std::vector<T>*, T*>> copies;
        std::vector<Lists> drained;  // waiting chunks placed now, kept alive for their copies
        {
            const std::lock_guard<std::mutex> lock(m_mutex);
            if (chunk != m_next) {
                m_waiting.emplace(chunk, lists);
                return;
            }
            place(chunk, lists, copies);
            drained.reserve(m_waiting.size());
            for (auto it = m_waiting.begin(); it != m_waiting.end() && it->first == m_next;) {
                drained.push_back(std::move(it->second));
                place(it->first, drained.back(), copies);
                it = m_waiting.erase(it);
            }
        }
        for (const auto& [from, to] : copies) std::copy(from->begin(), from->end(), to);
    }

    // A copy of chunk `chunk`'s list `list` (none if it was never put). Not while chunks are
    // being put.
    std::vector<T> items(size_t chunk, size_t list) const {
        if (chunk >= m_next) {
            const auto it = m_waiting.find(chunk);
            return it == m_waiting.end() ? std::vector<T>{} : it->second[list];
        }
        const Array& a = m_arrays[list];
        if (const auto it = a.overflow.find(chunk); it != a.overflow.end()) return it->second;
        const size_t first = m_at[chunk][list];
        const size_t last =
            chunk + 1 < m_next && !a.overflow.contains(chunk + 1) ? m_at[chunk + 1][list] : a.size;
        return std::vector<T>(a.data.get() + first, a.data.get() + last);
    }

    // Whether every chunk has been put.
    bool complete() const { return m_next == m_at.size(); }

    // Array `list`: every chunk's list `list` in chunk order; `count` is set to their number.
    // Takes the array out (once per list, after every chunk is in).
    std::unique_ptr<T[]> take(size_t list, size_t& count) {
        Array& a = m_arrays[list];
        count = a.size;
        if (a.overflow.empty()) return std::move(a.data);
        for (const auto& [chunk, items] : a.overflow) count += items.size();
        auto out = std::make_unique_for_overwrite<T[]>(count);
        T* end = std::copy(a.data.get(), a.data.get() + a.size, out.get());
        for (const auto& [chunk, items] : a.overflow)
            end = std::copy(items.begin(), items.end(), end);
        a = Array{};
        return out;
    }

private:
    struct Array {
        std::unique_ptr<T[]> data;
        size_t size = 0, capacity = 0;
        std::map<size_t, std::vector<T>> overflow;  // chunks past the capacity, in order
    };

    // Gives chunk `chunk`, the next in order, its places; the copies to make are added to
    // `copies`. Under the lock.
    void place(size_t chunk, const Lists& lists,
               std::vector<std::pair<const std::vector<T>*, T*>>& copies) {
        for (size_t l = 0; l < kLists; ++l) {
            Array& a = m_arrays[l];
            m_at[chunk][l] = a.size;
            if (a.overflow.empty() && a.size + lists[l].size() <= a.capacity) {
                copies.emplace_back(&lists[l], a.data.get() + a.size);
                a.size += lists[l].size();
            } else {
                a.overflow.emplace(chunk, lists[l]);
            }
        }
        ++m_next;
    }

    std::mutex m_mutex;
    size_t m_next = 0;  // the first chunk not yet placed
    std::array<Array, kLists> m_arrays;
    std::vector<std::array<size_t, kLists>> m_at;  // where each placed chunk's lists begin
    std::map<size_t, Lists> m_waiting;             // chunks put before an earlier one
    tbb::enumerable_thread_specific<Lists> m_scratch;
};

}  // namespace lenslab
