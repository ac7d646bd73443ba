// The single-process communicator, dealing, and the exchanges built on them (src/cluster/).
// The same exchanges across real ranks are checked by mpi_run.sh (cluster_tests.cmake).

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <vector>

#include "cluster/byte_packing.h"
#include "cluster/cluster_session.h"
#include "cluster/dealt_parts.h"
#include "cluster/local_communicator.h"
#include "cluster/rank_order_sum.h"
#include "render/render_control.h"
#include "util/error.h"

namespace lenslab {
namespace {

Bytes cluster_test_bytes(std::initializer_list<int> values) {
    Bytes out;
    for (int v : values) out.push_back(static_cast<std::byte>(v));
    return out;
}

TEST(Cluster, AloneIsRankZeroOfOne) {
    Communicator& alone = this_process_alone();
    EXPECT_EQ(alone.rank(), 0);
    EXPECT_EQ(alone.size(), 1);
    EXPECT_TRUE(alone.is_root());
    EXPECT_TRUE(alone.alone());
    alone.barrier();  // returns at once
}

TEST(Cluster, AloneExchangesGiveBackItsOwnBytes) {
    LocalCommunicator alone;
    const Bytes mine = cluster_test_bytes({1, 2, 3});
    const std::vector<Bytes> all = alone.all_gather(mine);
    ASSERT_EQ(all.size(), 1u);
    EXPECT_EQ(all[0], mine);
    const std::vector<Bytes> at_root = alone.gather_to_root(mine);
    ASSERT_EQ(at_root.size(), 1u);
    EXPECT_EQ(at_root[0], mine);
    Bytes b = mine;
    alone.broadcast(b);
    EXPECT_EQ(b, mine);
}

TEST(Cluster, DealsRoundRobin) {
    // Items 0..6 over 3 ranks: 0 3 6 | 1 4 | 2 5.
    std::vector<int> owner;
    for (int item = 0; item < 7; ++item) {
        int owners = 0;
        for (int rank = 0; rank < 3; ++rank) {
            if (dealt_to(item, rank, 3)) {
                owner.push_back(rank);
                ++owners;
            }
        }
        EXPECT_EQ(owners, 1) << "item " << item;
    }
    EXPECT_EQ(owner, (std::vector<int>{0, 1, 2, 0, 1, 2, 0}));
    for (int item = 0; item < 5; ++item) EXPECT_TRUE(dealt_to(item, this_process_alone()));
}

TEST(Cluster, SharingPartsAloneKeepsThemAll) {
    std::vector<std::vector<uint32_t>> parts{{1, 2}, {}, {3}};
    share_dealt_parts(this_process_alone(), parts);
    EXPECT_EQ(parts, (std::vector<std::vector<uint32_t>>{{1, 2}, {}, {3}}));
    gather_dealt_parts_to_root(this_process_alone(), parts);
    EXPECT_EQ(parts[2], std::vector<uint32_t>{3});
}

TEST(Cluster, PackedPartsUnpackOnAnotherRankInItemOrder) {
    // What rank 1 of 2 sends (items 1 and 3), as rank 0 reads it.
    struct FakeRank final : Communicator {
        int rank() const override { return 1; }
        int size() const override { return 2; }
        void barrier() override {}
        std::vector<Bytes> all_gather(std::span<const std::byte>) override { return {}; }
        std::vector<Bytes> gather_to_root(std::span<const std::byte>) override { return {}; }
        void broadcast(Bytes&) override {}
    } rank1;
    const std::vector<std::vector<double>> sent{{}, {1.5}, {}, {2.5, 3.5}};
    const Bytes message = detail::pack_dealt_parts(rank1, sent);
    std::vector<std::vector<double>> got{{9}, {}, {8}, {}};
    detail::unpack_dealt_parts(message, 1, 2, got);
    EXPECT_EQ(got, (std::vector<std::vector<double>>{{9}, {1.5}, {8}, {2.5, 3.5}}));
}

TEST(Cluster, SumsAloneAreTheValuesThemselves) {
    std::vector<double> d{0.1, 0.2};
    std::vector<uint64_t> u{7, 9};
    sum_in_rank_order(this_process_alone(), d);
    sum_in_rank_order(this_process_alone(), u);
    EXPECT_EQ(d, (std::vector<double>{0.1, 0.2}));
    EXPECT_EQ(u, (std::vector<uint64_t>{7, 9}));
}

// Rank 0 of three, whose ranks 1 and 2 sent `others` (what MPI would deliver).
struct ClusterTestRoot final : Communicator {
    std::vector<Bytes> others;
    int rank() const override { return 0; }
    int size() const override { return 3; }
    void barrier() override {}
    std::vector<Bytes> all_gather(std::span<const std::byte> mine) override {
        return gather_to_root(mine);
    }
    std::vector<Bytes> gather_to_root(std::span<const std::byte> mine) override {
        std::vector<Bytes> all{Bytes(mine.begin(), mine.end())};
        all.insert(all.end(), others.begin(), others.end());
        return all;
    }
    void broadcast(Bytes&) override {}  // the root keeps what it sends
};

TEST(Cluster, SumsAddTheRanksInRankOrder) {
    // Floating-point addition is not associative: (1e16 + -1e16) + 1 = 1, but
    // 1e16 + (-1e16 + 1) = 0. Rank order 0, 1, 2 must give the first, every time (which
    // MPI_Allreduce does not promise).
    const double a = 1e16, b = -1e16, c = 1.0;
    ASSERT_NE((a + b) + c, a + (b + c));
    ClusterTestRoot root;
    for (double v : {b, c}) {
        Bytes part;
        append_value(part, v);
        append_value(part, 2.0);
        root.others.push_back(part);
    }
    std::vector<double> values{a, 2.0};
    sum_in_rank_order(root, values);
    EXPECT_EQ(values, (std::vector<double>{(a + b) + c, 6.0}));

    ClusterTestRoot counts;
    for (uint64_t v : {uint64_t{2}, uint64_t{3}}) {
        Bytes part;
        append_value(part, v);
        counts.others.push_back(part);
    }
    std::vector<uint64_t> n{1};
    sum_in_rank_order(counts, n);
    EXPECT_EQ(n[0], 6u);
}

TEST(Cluster, SumsRefuseArraysOfDifferentLengths) {
    ClusterTestRoot root;
    root.others = {Bytes(8), Bytes(16)};
    std::vector<double> values{1.0};
    EXPECT_THROW(sum_in_rank_order(root, values), std::logic_error);
}

TEST(Cluster, RootGetsEveryRanksPartsInItemOrder) {
    // Items 0..5 over 3 ranks: rank 1 has 1 and 4, rank 2 has 2 and 5.
    ClusterTestRoot root;
    Bytes from1, from2;
    for (uint64_t item : {1, 4}) {
        append_value(from1, uint64_t{1});
        append_value(from1, static_cast<int>(10 * item));
    }
    for (uint64_t item : {2, 5}) {
        append_value(from2, uint64_t{1});
        append_value(from2, static_cast<int>(10 * item));
    }
    root.others = {from1, from2};
    std::vector<std::vector<int>> parts{{0}, {}, {}, {30}, {}, {}};
    gather_dealt_parts_to_root(root, parts);
    EXPECT_EQ(parts, (std::vector<std::vector<int>>{{0}, {10}, {20}, {30}, {40}, {50}}));
}

TEST(Cluster, BytesRoundTrip) {
    Bytes b;
    append_value(b, uint64_t{42});
    const std::vector<float> f{1.f, 2.f};
    append_bytes(b, std::span<const float>(f));
    ByteReader in(b);
    EXPECT_EQ(in.value<uint64_t>(), 42u);
    std::vector<float> back(2);
    in.read_into(std::span<float>(back));
    EXPECT_EQ(back, f);
    EXPECT_THROW(in.value<int>(), std::logic_error);
    int v = 5;
    broadcast_value(this_process_alone(), v);
    EXPECT_EQ(v, 5);
}

TEST(Cluster, RenderControlDefaultsToThisProcessAlone) {
    RenderControl control;
    EXPECT_EQ(&control.cluster(), &this_process_alone());
    LocalCommunicator other;
    control.set_cluster(other);
    EXPECT_EQ(&control.cluster(), &other);
}

TEST(Cluster, NoSessionMeansThisProcessAlone) {
    EXPECT_EQ(&world_communicator(), &this_process_alone());
}

TEST(Cluster, FaultHooksActOnlyInJobsOfSeveralRanks) {
    setenv("LENSLAB_TEST_FAIL_RANK", "0", 1);
    EXPECT_NO_THROW(cluster_fault_point(this_process_alone()));
    EXPECT_THROW(cluster_fault_point(ClusterTestRoot{}), Error);
    setenv("LENSLAB_TEST_FAIL_RANK", "2", 1);
    EXPECT_NO_THROW(cluster_fault_point(ClusterTestRoot{}));
    unsetenv("LENSLAB_TEST_FAIL_RANK");
}

}  // namespace
}  // namespace lenslab
