#pragma once

namespace lenslab {
class RenderControl;
}

namespace lenslab::cli {

// While one lives, the first Ctrl-C (SIGINT) asks `control` to stop; SA_RESETHAND makes a
// second one end the process at once. release() (or the destructor) puts the default back.
// One at a time: the handler reaches the control through one process-wide pointer.
class InterruptCancels {
public:
    explicit InterruptCancels(RenderControl& control);
    ~InterruptCancels();
    InterruptCancels(const InterruptCancels&) = delete;
    InterruptCancels& operator=(const InterruptCancels&) = delete;
    void release();

private:
    bool m_active = true;
};

}  // namespace lenslab::cli
