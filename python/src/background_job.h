#pragma once
// Long work (a render, a detection) on a thread of its own while the calling thread, the GIL
// released between polls, delivers progress to Python and watches for Ctrl-C. Both stop the
// work through its RenderControl, and the Python exception (KeyboardInterrupt, or whatever the
// progress callback raised) goes up.

#include <pybind11/pybind11.h>

#include <chrono>
#include <functional>

#include "render/background_work.h"

namespace lenslab::python {

// How often the calling thread looks at the work: Ctrl-C answers within about this.
constexpr auto kPollInterval = std::chrono::milliseconds(20);

// Work running on its own thread (render/background_work.h). Destroying it while the work
// runs (an exception in the caller) cancels the work and waits for it, the GIL released.
template <class Result>
class BackgroundJob {
public:
    explicit BackgroundJob(std::function<Result(RenderControl&)> work) : m_work(std::move(work)) {}
    ~BackgroundJob() {
        pybind11::gil_scoped_release unlocked;
        m_work.stop();
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
                done = m_work.wait_for(kPollInterval);
            }
            const double fraction = m_work.progress();
            if (!progress.is_none() && fraction != reported) {
                reported = fraction;
                progress(fraction);
            }
            // Runs Python's SIGINT handler on the main thread: KeyboardInterrupt on Ctrl-C.
            if (!done && PyErr_CheckSignals() != 0) throw pybind11::error_already_set();
        }
        return m_work.get();
    }
    const RenderControl& control() const { return m_work.control(); }

private:
    BackgroundWork<Result> m_work;
};

}  // namespace lenslab::python
