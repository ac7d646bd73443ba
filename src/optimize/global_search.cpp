#include "optimize/global_search.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <mutex>
#include <span>

#include "cluster/byte_packing.h"
#include "cluster/cluster_session.h"
#include "cluster/dealt_parts.h"
#include "math/halton.h"
#include "math/rng.h"
#include "optimize/local_search.h"
#include "util/scene_error.h"

namespace lenslab {

namespace {

// Enough primes for a dimension per variable of any design lenslab reads in practice; past
// them the coordinates repeat primes (still spread, less evenly).
constexpr std::array<uint64_t, 24> kPrimes = {2,  3,  5,  7,  11, 13, 17, 19, 23, 29, 31, 37,
                                              41, 43, 47, 53, 59, 61, 67, 71, 73, 79, 83, 89};

// Start `index` (>= 1) of the sequence: every drawn variable at its rotated Halton coordinate.
std::vector<double> gs_point(const std::vector<SearchRange>& ranges,
                             const std::vector<double>& rotation, const std::vector<double>& x0,
                             uint64_t index) {
    std::vector<double> x = x0;
    int dimension = 0;
    for (size_t i = 0; i < ranges.size(); ++i) {
        if (!(ranges[i].hi > ranges[i].lo)) continue;
        double u =
            radical_inverse_of(kPrimes[dimension % kPrimes.size()], index) + rotation[dimension];
        if (u >= 1.0) u -= 1.0;
        x[i] = ranges[i].lo + u * (ranges[i].hi - ranges[i].lo);
        ++dimension;
    }
    return x;
}

// A run as the ranks of a job exchange it: nothing for a start that cannot be evaluated,
// else the merit, counts, why it stopped and where it ended, bit for bit.
Bytes gs_pack(const std::optional<LmResult>& run) {
    Bytes out;
    if (!run) return out;
    append_value(out, run->merit);
    append_value(out, int64_t(run->iterations));
    append_value(out, int64_t(run->evaluations));
    append_value(out, uint64_t(run->stopped.size()));
    append_bytes(out, std::span<const char>(run->stopped));
    append_value(out, uint64_t(run->x.size()));
    append_bytes(out, std::span<const double>(run->x));
    return out;
}

std::optional<LmResult> gs_unpack(const Bytes& bytes) {
    if (bytes.empty()) return std::nullopt;
    ByteReader in(bytes);
    LmResult run;
    run.merit = in.value<double>();
    run.iterations = int(in.value<int64_t>());
    run.evaluations = int(in.value<int64_t>());
    run.stopped.resize(in.value<uint64_t>());
    in.read_into(std::span<char>(run.stopped));
    run.x.resize(in.value<uint64_t>());
    in.read_into(std::span<double>(run.x));
    return run;
}

// Runs `iterations` from `x`; none where the point cannot be evaluated.
std::optional<LmResult> gs_run(const DesignModel& model, const std::vector<double>& x,
                               int iterations) {
    if (!model.evaluate(x)) return std::nullopt;
    return local_search(model, x, iterations);
}

}  // namespace

std::vector<SearchRange> search_ranges(const DesignModel& model) {
    const std::vector<double> x0 = model.start();
    std::vector<SearchRange> ranges;
    for (size_t i = 0; i < x0.size(); ++i) {
        const DesignVariable& v = model.design().variables[i];
        if (v.bounded()) {
            ranges.push_back({*v.min, *v.max});
        } else if (v.kind == VariableKind::Curvature && v.semi_diameter > 0) {
            const double c = 0.5 / v.semi_diameter;
            ranges.push_back({-c, c});
        } else {
            ranges.push_back({x0[i], x0[i]});
        }
    }
    return ranges;
}

GlobalSearchResult global_search(const DesignModel& model, const GlobalSearchSettings& settings,
                                 int iterations,
                                 const std::function<void(const LmProgress&)>& progress) {
    const std::vector<double> x0 = model.start();
    const std::vector<SearchRange> ranges = search_ranges(model);
    Rng rng(settings.seed, 0x9106a15eULL);
    std::vector<double> rotation(ranges.size());
    for (double& r : rotation) r = rng.uniform();

    GlobalSearchResult result;
    const int count = std::max(settings.starts, 1);
    result.starts.resize(count);
    std::vector<std::optional<LmResult>> short_runs(count);
    // Progress as runs finish (in whatever order), one call at a time; it may throw to stop.
    std::mutex progress_mutex;
    int finished = 0, evaluations = 0;
    double best_merit = INFINITY;
    const auto report = [&](const LmResult& run) {
        if (!progress) return;
        const std::lock_guard<std::mutex> lock(progress_mutex);
        // (A start that cannot be evaluated ends without a run and is not counted.)
        best_merit = std::min(best_merit, run.merit);
        evaluations += run.evaluations;
        progress({++finished, best_merit, 0, evaluations});
    };
    // In a job of several ranks, start k is run by rank k mod N and the runs shared: every
    // rank then ranks and polishes as one process would (the polish runs dealt alike).
    Communicator& comm = world_communicator();
    for (int k = 0; k < count; ++k) {
        result.starts[k].index = k;
        result.starts[k].x = k == 0 ? x0 : gs_point(ranges, rotation, x0, static_cast<uint64_t>(k));
    }
    std::vector<Bytes> shared(static_cast<size_t>(count));
    tbb::parallel_for(0, count, [&](int k) {
        if (!dealt_to(k, comm)) return;
        const std::optional<LmResult> run =
            gs_run(model, result.starts[k].x, settings.start_iterations);
        if (run) report(*run);
        shared[size_t(k)] = gs_pack(run);
    });
    share_dealt_parts(comm, shared);
    for (int k = 0; k < count; ++k) {
        GlobalSearchStart& s = result.starts[k];
        short_runs[k] = gs_unpack(shared[size_t(k)]);
        s.evaluable = short_runs[k].has_value();
        if (s.evaluable) s.merit = short_runs[k]->merit;
    }
    for (const std::optional<LmResult>& run : short_runs) {
        if (run) result.evaluations += run->evaluations;
    }

    // The best few, ties to the earlier start, polished from where their short runs ended.
    std::vector<int> order;
    for (int k = 0; k < count; ++k) {
        if (result.starts[k].evaluable) order.push_back(k);
    }
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return result.starts[a].merit < result.starts[b].merit; });
    if (order.empty()) throw SceneError("global_search", "no start could be evaluated");
    order.resize(std::min<size_t>(order.size(), std::max(settings.keep, 1)));
    std::vector<Bytes> polished_shared(order.size());
    tbb::parallel_for(size_t{0}, order.size(), [&](size_t j) {
        if (!dealt_to(int64_t(j), comm)) return;
        const LmResult run = local_search(model, short_runs[order[j]]->x, iterations);
        report(run);
        polished_shared[j] = gs_pack(run);
    });
    share_dealt_parts(comm, polished_shared);
    std::vector<LmResult> polished(order.size());
    for (size_t j = 0; j < order.size(); ++j) polished[j] = *gs_unpack(polished_shared[j]);
    size_t best = 0;
    for (size_t j = 0; j < order.size(); ++j) {
        GlobalSearchStart& s = result.starts[order[j]];
        s.polished = true;
        s.polished_merit = polished[j].merit;
        result.evaluations += polished[j].evaluations;
        if (polished[j].merit < polished[best].merit) best = j;
    }
    result.chosen = order[best];
    result.solver = polished[best];
    result.solver.evaluations = result.evaluations;
    return result;
}

}  // namespace lenslab
