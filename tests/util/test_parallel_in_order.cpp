// parallel_for_in_order (util/parallel_in_order.h): every index once, begun in order, on
// several threads at once. Runs under ThreadSanitizer (the tsan preset's filter).

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

#include "util/parallel_in_order.h"

namespace lenslab {
namespace {

TEST(ParallelInOrder, EveryIndexOnceInOrderAtAnyThreadCount) {
    tbb::global_control most{tbb::global_control::max_allowed_parallelism, 8};
    for (int threads : {1, 2, 8}) {
        for (int64_t count : {0, 1, 7, 1000}) {
            std::vector<std::atomic<int>> calls(static_cast<size_t>(count));
            std::mutex mutex;
            std::map<std::thread::id, int64_t> last;  // each thread's latest index
            bool in_order = true;
            tbb::task_arena arena(threads);
            arena.execute([&] {
                parallel_for_in_order(count, [&](int64_t i) {
                    ++calls[static_cast<size_t>(i)];
                    // Each thread takes indices larger than any it had.
                    const std::lock_guard<std::mutex> lock(mutex);
                    const auto [at, first] = last.try_emplace(std::this_thread::get_id(), i);
                    if (!first && at->second >= i) in_order = false;
                    at->second = i;
                });
            });
            for (int64_t i = 0; i < count; ++i)
                EXPECT_EQ(calls[static_cast<size_t>(i)], 1) << i << " of " << count;
            EXPECT_TRUE(in_order) << threads << " threads";
            EXPECT_LE(last.size(), static_cast<size_t>(threads));
        }
    }
}

}  // namespace
}  // namespace lenslab
