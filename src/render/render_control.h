#pragma once
// Progress reporting and cancellation shared between a render and whoever started it, and
// the processes the render is split across (this one alone unless set: src/cluster/).

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <mutex>

#include "cluster/communicator.h"

namespace lenslab {

class RenderControl {
public:
    // Called with the finished fraction in [0, 1]; calls are serialised, from any thread, and
    // never go backwards (a worker that computed its fraction before another's may report it
    // after; it is then raised to the highest fraction already reported).
    using ProgressFn = std::function<void(double)>;

    RenderControl() = default;
    explicit RenderControl(ProgressFn fn) : m_progress(std::move(fn)) {}

    void cancel() { m_cancelled.store(true, std::memory_order_relaxed); }
    bool cancelled() const { return m_cancelled.load(std::memory_order_relaxed); }

    // A sample that came out NaN or infinite was left out of its pixel. It is a bug, but
    // the picture stays usable; the count lets the caller say so instead of staying silent.
    void count_non_finite_sample() { m_non_finite.fetch_add(1, std::memory_order_relaxed); }
    int64_t non_finite_samples() const { return m_non_finite.load(std::memory_order_relaxed); }

    // The ranks that render together: each does its dealt share and they exchange results
    // so that rank 0 ends with the image one process would make (the same bytes).
    Communicator& cluster() const { return *m_cluster; }
    void set_cluster(Communicator& comm) { m_cluster = &comm; }

    void report(double fraction) {
        if (!m_progress) return;
        std::lock_guard lock(m_mutex);
        m_reported = std::max(m_reported, fraction);
        m_progress(m_reported);
    }

private:
    ProgressFn m_progress;
    std::atomic<bool> m_cancelled{false};
    std::atomic<int64_t> m_non_finite{0};
    std::mutex m_mutex;
    double m_reported = 0;  // guarded by m_mutex
    Communicator* m_cluster = &this_process_alone();
};

}  // namespace lenslab
