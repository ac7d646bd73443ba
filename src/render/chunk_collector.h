#pragma once
// What parallel chunks of work deposit (photons), gathered in chunk order so the result does
// not depend on the threads. A chunk fills its thread's scratch lists, whose pages are
// faulted in once per thread rather than once per chunk, then puts a copy into one staging
// array backed by huge pages (util/huge_pages.h); join() copies the lists out in order.

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <memory>
#include <type_traits>
#include <vector>

#include "util/huge_pages.h"

namespace lenslab {

template <class T>
class ChunkCollector {
    static_assert(std::is_trivially_copyable_v<T>, "items are copied as bytes");

public:
    static constexpr int kScratchLists = 2;

    // `slots` numbered lists, about `expected` items in all: past it, a list keeps its own
    // storage (slower, never wrong).
    ChunkCollector(size_t slots, size_t expected)
        : m_staging(std::make_unique_for_overwrite<T[]>(expected)),
          m_capacity(expected),
          m_slots(slots) {
        advise_huge_pages(m_staging.get(), expected * sizeof(T));
    }

    // The calling thread's scratch list `which` (< kScratchLists), emptied.
    std::vector<T>& scratch(int which) {
        std::vector<T>& list = m_scratch.local()[static_cast<size_t>(which)];
        list.clear();
        return list;
    }

    // Keeps a copy of `items` as slot `slot`'s. Thread-safe; each slot at most once.
    void put(size_t slot, const std::vector<T>& items) {
        Slot& s = m_slots[slot];
        s.count = items.size();
        const size_t at = m_used.fetch_add(items.size(), std::memory_order_relaxed);
        if (at + items.size() <= m_capacity) {
            std::copy(items.begin(), items.end(), m_staging.get() + at);
            s.data = m_staging.get() + at;
        } else {
            s.own = items;
            s.data = s.own.data();
        }
    }

    // A copy of slot `slot`'s items (none if it was never put).
    std::vector<T> items(size_t slot) const {
        const Slot& s = m_slots[slot];
        return std::vector<T>(s.data, s.data + s.count);
    }

    // Every slot's items in slot order; `offset[s]` is where slot s's begin (`offset.back()`
    // the total). Frees the staging. The copy runs in parallel and is the first write to the
    // array, so its page faults are spread over the threads too.
    std::unique_ptr<T[]> join(std::vector<size_t>& offset) {
        offset.assign(m_slots.size() + 1, 0);
        for (size_t s = 0; s < m_slots.size(); ++s) offset[s + 1] = offset[s] + m_slots[s].count;
        auto out = std::make_unique_for_overwrite<T[]>(offset.back());
        advise_huge_pages(out.get(), offset.back() * sizeof(T));
        tbb::parallel_for(size_t{0}, m_slots.size(), [&](size_t s) {
            std::copy(m_slots[s].data, m_slots[s].data + m_slots[s].count, out.get() + offset[s]);
        });
        m_slots.clear();
        m_staging.reset();
        return out;
    }

private:
    struct Slot {
        const T* data = nullptr;
        size_t count = 0;
        std::vector<T> own;  // when the staging was full
    };

    std::unique_ptr<T[]> m_staging;
    size_t m_capacity;
    std::atomic<size_t> m_used{0};
    std::vector<Slot> m_slots;
    tbb::enumerable_thread_specific<std::array<std::vector<T>, kScratchLists>> m_scratch;
};

}  // namespace lenslab
