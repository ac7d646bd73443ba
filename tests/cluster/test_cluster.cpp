// The single-process communicator, dealing, and the exchanges built on them (src/cluster/).
// The same exchanges across real ranks are checked by mpi_run.sh (cluster_tests.cmake).

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "cluster/byte_packing.h"
#include "cluster/cluster_session.h"
#include "cluster/dealt_parts.h"
#include "cluster/local_communicator.h"
#include "cluster/rank_order_sum.h"
#include "render/render_control.h"

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

TEST(Cluster, RankOrderMattersForFloatingPointSums) {
    // Why the sums gather to rank 0 and add in rank order rather than use MPI_Allreduce:
    // floating-point addition is not associative, so another order can change the bits.
    const double a = 1e16, b = -1e16, c = 1.0;
    EXPECT_NE((a + b) + c, a + (b + c));
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
    unsetenv("LENSLAB_TEST_FAIL_RANK");
}

}  // namespace
}  // namespace lenslab
