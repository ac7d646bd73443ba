#pragma once
// Long work (a render, a detection) on a thread of its own while the calling thread, the GIL
// released between polls, delivers progress to Python and watches for Ctrl-C. Both stop the
// work through its RenderControl, and the Python exception (KeyboardInterrupt, or whatever the
// progress callback raised) goes up.

#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <functional>
#include <future>

#include "render/render_control.h"

namespace lenslab::python {

// How often the calling thread looks at the work: Ctrl-C answers within about this.
constexpr auto kPollInterval = std::chrono::milliseconds(20);

// Work running on its own thread. Destroying it while the work runs (an exception in the
// caller) cancels the work and waits for it, so it never outlives what it reads.
template <class Result>
class BackgroundJob {
public:
    // `work` is called on the new thread with the job's RenderControl; it must keep what it
    // reads alive until the job ends (the job's owner holds it).
    explicit BackgroundJob(std::function<Result(RenderControl&)> work)
        : m_work(std::move(work)),
          m_control([this](double fraction) { m_progress.store(fraction); }) {
        m_result = std::async(std::launch::async, [this] { return m_work(m_control); });
    }
    ~BackgroundJob() {
        if (!m_result.valid()) return;
        m_control.cancel();
        pybind11::gil_scoped_release unlocked;
        m_result.wait();
    }
    BackgroundJob(const BackgroundJob&) = delete;
    BackgroundJob& operator=(const BackgroundJob&) = delete;

    // Polls until the work ends, calling `progress` (unless None) with each new finished
    // fraction; raises KeyboardInterrupt on Ctrl-C and whatever `progress` raises, either of
    // which cancels the work (~BackgroundJob). Returns the work's result or rethrows its
    // exception.
    Result run(const pybind11::object& progress) {
        double reported = -1.0;
        for (bool done = false; !done;) {
            {
                pybind11::gil_scoped_release unlocked;
                done = m_result.wait_for(kPollInterval) == std::future_status::ready;
            }
            const double fraction = m_progress.load();
            if (!progress.is_none() && fraction != reported) {
                reported = fraction;
                progress(fraction);
            }
            // Runs Python's SIGINT handler on the main thread: KeyboardInterrupt on Ctrl-C.
            if (!done && PyErr_CheckSignals() != 0) throw pybind11::error_already_set();
        }
        return m_result.get();
    }
    const RenderControl& control() const { return m_control; }

private:
    std::function<Result(RenderControl&)> m_work;
    std::atomic<double> m_progress{-1.0};
    RenderControl m_control;
    std::future<Result> m_result;
};

}  // namespace lenslab::python
