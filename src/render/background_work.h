#pragma once
// Long work (a render, a detection, a batch of analyses) on a thread of its own, stopped
// through its RenderControl and reporting its finished fraction, while the thread that started
// it polls: the Python module's way of running the library (python/src/background_job.h adds
// the GIL and Ctrl-C around it). Without Python in it, the ThreadSanitizer stage checks it.

#include <atomic>
#include <chrono>
#include <functional>
#include <future>

#include "render/render_control.h"

namespace lenslab {

template <class Result>
class BackgroundWork {
public:
    // `work` is called on the new thread with the work's RenderControl; what it reads must
    // outlive the work (its owner holds it).
    explicit BackgroundWork(std::function<Result(RenderControl&)> work)
        : m_work(std::move(work)),
          m_control([this](double fraction) { m_progress.store(fraction); }) {
        m_result = std::async(std::launch::async, [this] { return m_work(m_control); });
    }
    // Destroyed while the work runs (an exception in the poller), it cancels the work and
    // waits for it, so the work never outlives what it reads.
    ~BackgroundWork() { stop(); }
    BackgroundWork(const BackgroundWork&) = delete;
    BackgroundWork& operator=(const BackgroundWork&) = delete;

    // True once the work has ended, after waiting at most `timeout` for it.
    bool wait_for(std::chrono::milliseconds timeout) const {
        return m_result.wait_for(timeout) == std::future_status::ready;
    }
    // The last finished fraction the work reported; -1 before the first.
    double progress() const { return m_progress.load(); }
    // Cancels the work unless it has ended, and waits for it.
    void stop() {
        if (!m_result.valid()) return;
        m_control.cancel();
        m_result.wait();
    }
    // The work's result, or its exception rethrown; once.
    Result get() { return m_result.get(); }
    const RenderControl& control() const { return m_control; }

private:
    std::function<Result(RenderControl&)> m_work;
    std::atomic<double> m_progress{-1.0};
    RenderControl m_control;
    std::future<Result> m_result;
};

}  // namespace lenslab
