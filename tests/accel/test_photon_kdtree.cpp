// The photon kd-tree returns exactly what brute force returns.

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "accel/photon_kdtree.h"
#include "math/rng.h"
#include "math/sampling.h"

namespace lenslab {
namespace {

std::vector<Photon> random_photons(size_t n, uint64_t seed, bool clustered) {
    Rng rng(seed, 0);
    std::vector<Photon> out(n);
    for (Photon& p : out) {
        Vec3 v{rng.uniform(), rng.uniform(), rng.uniform()};
        if (clustered) v = v * v.x * v.x;  // dense near the origin, with duplicates of x
        p.position[0] = static_cast<float>(v.x);
        p.position[1] = static_cast<float>(v.y);
        p.position[2] = static_cast<float>(clustered ? 0.0 : v.z);  // a flat layer, like a floor
        p.power[0] = p.power[1] = p.power[2] = 1.0f;
        encode_octahedral(sample_uniform_sphere(rng.uniform(), rng.uniform()), p.towards);
        p.kind = PhotonKind::Direct;
    }
    return out;
}

// Brute force: all photons within the radius (facing filter applied), nearest first. The
// squared distances in float, as the tree computes them from its float positions.
std::vector<float> brute(const std::vector<Photon>& photons, const Vec3& x, double radius, size_t k,
                         const Vec3* facing) {
    std::vector<float> d2;
    const float p[3] = {float(x.x), float(x.y), float(x.z)};
    for (const Photon& ph : photons) {
        const float dx = p[0] - ph.position[0], dy = p[1] - ph.position[1],
                    dz = p[2] - ph.position[2];
        const float d = dx * dx + dy * dy + dz * dz;
        if (d >= static_cast<float>(radius * radius)) continue;
        if (facing && dot(ph.incoming(), *facing) <= 0.0) continue;
        d2.push_back(d);
    }
    std::sort(d2.begin(), d2.end());
    if (d2.size() > k) d2.resize(k);
    return d2;
}

class KdTreeVsBruteForce : public testing::TestWithParam<bool> {};

TEST_P(KdTreeVsBruteForce, RadiusAndNearestQueriesAgree) {
    const bool clustered = GetParam();
    const std::vector<Photon> reference = random_photons(20000, 11, clustered);
    std::vector<Photon> photons = reference;
    const PhotonKdTree tree(photons.data(), photons.size());
    Rng rng(3, 0);
    std::vector<PhotonNeighbour> found;
    for (int q = 0; q < 300; ++q) {
        const Vec3 x{rng.uniform(), rng.uniform(), clustered ? 0.0 : rng.uniform()};
        const double radius = 0.01 + 0.2 * rng.uniform();
        const Vec3 facing = sample_uniform_sphere(rng.uniform(), rng.uniform());
        for (size_t k : {size_t{1}, size_t{7}, size_t{50}, size_t{1000000}}) {
            for (const Vec3* f : {static_cast<const Vec3*>(nullptr), &facing}) {
                const std::vector<float> expected = brute(reference, x, radius, k, f);
                const double r2 = tree.nearest(x, radius, k, f, found);
                std::vector<float> got;
                for (const auto& nb : found) got.push_back(nb.dist2);
                std::sort(got.begin(), got.end());
                ASSERT_EQ(got, expected) << "query " << q << " k " << k;
                if (expected.size() == k) {
                    EXPECT_FLOAT_EQ(static_cast<float>(r2), expected.back());
                } else {
                    EXPECT_DOUBLE_EQ(r2, radius * radius);
                }
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Sets, KdTreeVsBruteForce, testing::Values(false, true),
                         [](const auto& p) { return p.param ? "Clustered" : "Uniform"; });

TEST(PhotonKdTree, EmptyAndSingleton) {
    std::vector<PhotonNeighbour> found;
    const PhotonKdTree empty(nullptr, 0);
    EXPECT_DOUBLE_EQ(empty.nearest({0, 0, 0}, 1.0, 10, nullptr, found), 1.0);
    EXPECT_TRUE(found.empty());
    std::vector<Photon> one = random_photons(1, 5, false);
    const PhotonKdTree tree(one.data(), 1);
    tree.nearest(one[0].pos(), 0.1, 10, nullptr, found);
    EXPECT_EQ(found.size(), 1u);
}

TEST(Photon, OctahedralDirectionsRoundTrip) {
    Rng rng(9, 0);
    for (int i = 0; i < 10000; ++i) {
        const Vec3 v = sample_uniform_sphere(rng.uniform(), rng.uniform());
        uint16_t enc[2];
        encode_octahedral(v, enc);
        EXPECT_GT(dot(decode_octahedral(enc), v), 1.0 - 1e-8);  // within ~1.4e-4 rad
    }
}

}  // namespace
}  // namespace lenslab
