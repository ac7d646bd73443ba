#pragma once
// Progress reporting and cancellation shared between a render and whoever started it.

#include <atomic>
#include <functional>
#include <mutex>

namespace lenslab {

class RenderControl {
public:
    // Called with the finished fraction in [0, 1]; calls are serialised, from any thread.
    using ProgressFn = std::function<void(double)>;

    RenderControl() = default;
    explicit RenderControl(ProgressFn fn) : m_progress(std::move(fn)) {}

    void cancel() { m_cancelled.store(true, std::memory_order_relaxed); }
    bool cancelled() const { return m_cancelled.load(std::memory_order_relaxed); }

    void report(double fraction) {
        if (!m_progress) return;
        std::lock_guard lock(m_mutex);
        m_progress(fraction);
    }

private:
    ProgressFn m_progress;
    std::atomic<bool> m_cancelled{false};
    std::mutex m_mutex;
};

}  // namespace lenslab
