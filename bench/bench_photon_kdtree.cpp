// Our implicit photon kd-tree against nanoflann (nanoflann is the default choice unless a
// benchmark shows our own is faster). Same photons, same queries: k nearest within a radius.

#include <benchmark/benchmark.h>

#include <nanoflann.hpp>
#include <vector>

#include "accel/photon_kdtree.h"
#include "math/rng.h"

namespace lenslab {
namespace {

// A floor-like layer of photons, denser in the middle (like a caustic).
std::vector<Photon> floor_photons(size_t n) {
    Rng rng(1, 0);
    std::vector<Photon> out(n);
    for (Photon& p : out) {
        const double u = rng.uniform(), v = rng.uniform();
        p.position[0] = static_cast<float>((u - 0.5) * (0.2 + 5.8 * rng.uniform()));
        p.position[1] = 0.0f;
        p.position[2] = static_cast<float>((v - 0.5) * 6.0);
        p.power[0] = p.power[1] = p.power[2] = 1.0f;
        encode_octahedral({0, 1, 0}, p.towards);
    }
    return out;
}

std::vector<Vec3> queries(size_t n) {
    Rng rng(2, 0);
    std::vector<Vec3> q(n);
    for (Vec3& x : q) x = {(rng.uniform() - 0.5) * 6.0, 0.0, (rng.uniform() - 0.5) * 6.0};
    return q;
}

struct Cloud {
    const std::vector<Photon>& pts;
    size_t kdtree_get_point_count() const { return pts.size(); }
    float kdtree_get_pt(size_t i, size_t dim) const { return pts[i].position[dim]; }
    template <class B>
    bool kdtree_get_bbox(B&) const {
        return false;
    }
};
using NanoTree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, Cloud>, Cloud, 3>;

constexpr size_t kPhotons = 1000000;
constexpr double kRadius = 0.05;
constexpr size_t kMaxPhotons = 200;

void BM_BuildOurs(benchmark::State& state) {
    const auto base = floor_photons(kPhotons);
    for (auto _ : state) {
        state.PauseTiming();
        auto photons = base;
        state.ResumeTiming();
        PhotonKdTree tree(photons.data(), photons.size());
        benchmark::DoNotOptimize(photons.data());
    }
}

void BM_BuildNanoflann(benchmark::State& state) {
    const auto photons = floor_photons(kPhotons);
    const Cloud cloud{photons};
    for (auto _ : state) {
        NanoTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
        tree.buildIndex();
        benchmark::DoNotOptimize(tree.root_node);
    }
}

void BM_QueryOurs(benchmark::State& state) {
    auto photons = floor_photons(kPhotons);
    const PhotonKdTree tree(photons.data(), photons.size());
    const auto q = queries(4096);
    std::vector<PhotonNeighbour> out;
    size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(tree.nearest(q[i++ & 4095], kRadius, kMaxPhotons, nullptr, out));
    }
    state.SetItemsProcessed(state.iterations());
}

void BM_QueryNanoflann(benchmark::State& state) {
    // nanoflann 1.4 has no radius-bounded k-nearest search: a radius search, then keep the
    // k nearest, which is what our estimate needs.
    const auto photons = floor_photons(kPhotons);
    const Cloud cloud{photons};
    NanoTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
    tree.buildIndex();
    const auto q = queries(4096);
    std::vector<std::pair<uint32_t, float>> matches;
    nanoflann::SearchParams params;
    params.sorted = false;
    size_t i = 0;
    for (auto _ : state) {
        const Vec3& x = q[i++ & 4095];
        const float p[3] = {float(x.x), float(x.y), float(x.z)};
        tree.radiusSearch(p, static_cast<float>(kRadius * kRadius), matches, params);
        if (matches.size() > kMaxPhotons) {
            std::nth_element(matches.begin(), matches.begin() + kMaxPhotons, matches.end(),
                             [](const auto& a, const auto& b) { return a.second < b.second; });
            matches.resize(kMaxPhotons);
        }
        benchmark::DoNotOptimize(matches.data());
    }
    state.SetItemsProcessed(state.iterations());
}

BENCHMARK(BM_BuildOurs)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BuildNanoflann)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_QueryOurs);
BENCHMARK(BM_QueryNanoflann);

}  // namespace
}  // namespace lenslab
