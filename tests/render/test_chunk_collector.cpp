// Chunks handed in by several threads in any order come out in chunk order, written once,
// whether they fit the arrays' capacity or spill past it.

#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <numeric>
#include <vector>

#include "render/chunk_collector.h"

namespace lenslab {
namespace {

// Chunk c deposits c % 7 items in list 0 and (c * 3) % 5 in list 1, each the value
// 1000 * c + its index, so the expected order is known.
ChunkCollector<int>::Lists deposits_of(size_t chunk) {
    ChunkCollector<int>::Lists lists;
    for (size_t i = 0; i < chunk % 7; ++i) lists[0].push_back(int(1000 * chunk + i));
    for (size_t i = 0; i < chunk * 3 % 5; ++i) lists[1].push_back(int(1000 * chunk + i));
    return lists;
}

std::vector<int> expected_list(size_t chunks, size_t list) {
    std::vector<int> all;
    for (size_t c = 0; c < chunks; ++c) {
        const auto lists = deposits_of(c);
        all.insert(all.end(), lists[list].begin(), lists[list].end());
    }
    return all;
}

void put_in_parallel(ChunkCollector<int>& found, size_t chunks) {
    // Chunks begun from the back and the front at once, so most arrive out of order.
    tbb::parallel_for(size_t{0}, chunks, [&](size_t k) {
        const size_t chunk = k % 2 ? chunks - 1 - k / 2 : k / 2;
        ChunkCollector<int>::Lists& lists = found.scratch();
        lists = deposits_of(chunk);
        found.put(chunk, lists);
    });
}

class ChunkCollectorCapacity : public ::testing::TestWithParam<size_t> {};

TEST_P(ChunkCollectorCapacity, JoinsInChunkOrderFromAnyThread) {
    constexpr size_t kChunks = 400;
    ChunkCollector<int> found(kChunks, GetParam());
    put_in_parallel(found, kChunks);
    ASSERT_TRUE(found.complete());
    // items() before take(): what the cluster's exchange reads.
    for (size_t c : {size_t{0}, size_t{1}, size_t{57}, size_t{200}, kChunks - 1}) {
        EXPECT_EQ(found.items(c, 0), deposits_of(c)[0]) << "chunk " << c;
        EXPECT_EQ(found.items(c, 1), deposits_of(c)[1]) << "chunk " << c;
    }
    for (size_t list = 0; list < 2; ++list) {
        size_t count = 0;
        const std::unique_ptr<int[]> all = found.take(list, count);
        const std::vector<int> expected = expected_list(kChunks, list);
        ASSERT_EQ(count, expected.size());
        EXPECT_TRUE(std::equal(expected.begin(), expected.end(), all.get())) << "list " << list;
    }
}

// Ample room, room for about half (the rest spills), and none at all.
INSTANTIATE_TEST_SUITE_P(Room, ChunkCollectorCapacity, ::testing::Values(4000, 600, 0));

TEST(ChunkCollector, IncompleteUntilEveryChunkIsIn) {
    ChunkCollector<int> found(3, 100);
    found.put(2, deposits_of(2));
    found.put(0, deposits_of(0));
    EXPECT_FALSE(found.complete());
    EXPECT_EQ(found.items(2, 0), deposits_of(2)[0]);  // still waiting for chunk 1
    found.put(1, deposits_of(1));
    EXPECT_TRUE(found.complete());
}

}  // namespace
}  // namespace lenslab
