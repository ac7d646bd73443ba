#pragma once
// A parallel loop whose items are begun in order: each thread takes the next index from a
// shared counter. tbb::parallel_for splits its range in halves and hands a thread a run of
// items it cannot give away once begun, so work kept in order (photon chunks joined in chunk
// order) waited for a whole half, and a run of slow tiles left the other core idle at the end
// of a render. Here every thread is busy until the last item is begun.

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cstdint>

namespace lenslab {

// Calls `body(i)` for every i in [0, count), on the threads of the current task arena.
template <class Body>
void parallel_for_in_order(int64_t count, const Body& body) {
    if (count <= 0) return;
    std::atomic<int64_t> next{0};
    const int64_t threads = std::min<int64_t>(tbb::this_task_arena::max_concurrency(), count);
    tbb::parallel_for(int64_t{0}, threads, [&](int64_t) {
        for (int64_t i = next++; i < count; i = next++) body(i);
    });
}

}  // namespace lenslab
